// Runs a Shadertoy buffer pass (Buffer A-D of a project): fragColor is stored
// as written, unclamped, in a float target that later passes sample.
out vec4 o_color;
void main() {
  vec4 c = vec4(0.0);
  mainImage(c, gl_FragCoord.xy);
  o_color = c;
}
