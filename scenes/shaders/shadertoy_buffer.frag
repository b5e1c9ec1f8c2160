// Runs a Shadertoy buffer pass (Buffer A-D of a project): fragColor is stored
// as written, unclamped, in a float target that later passes sample. Names
// have the foveate_ prefix so that the user's macros do not replace them.
out vec4 foveate_out;
void main() {
  vec4 foveate_color = vec4(0.0);
  mainImage(foveate_color, gl_FragCoord.xy);
  foveate_out = foveate_color;
}
