// Not a Shadertoy shader: no mainImage.
void main() { gl_FragColor = vec4(1.0); }
