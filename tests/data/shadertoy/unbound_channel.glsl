// Samples iChannel1 (and iChannel0, bound by --channel in the test): with
// nothing bound to iChannel1 it reads black, and foveate warns.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.xy;
  // iChannel3 in a comment is not a use.
  fragColor = vec4(texture(iChannel1, uv).rgb + 0.5 * texture(iChannel0, uv).rgb, 1.0);
}
