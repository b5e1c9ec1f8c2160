// Compiles a scene's shading function on its own, to report errors at load.
out vec4 o_color;
void main() { o_color = scene_shade(gl_FragCoord.xy); }
