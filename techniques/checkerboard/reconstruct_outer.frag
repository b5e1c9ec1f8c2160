// Reconstruction, last pass, beyond the blend band: the filtered image alone
// (every pixel there is drawn from it; kept samples lie within any Gaussian's
// reach, so the coverage is never zero).
#include "checkerboard/filtered.glsl"
layout(early_fragment_tests) in;
out vec4 o_color;
void main() {
  vec4 s = filtered_sums(gl_FragCoord.xy);
  o_color = vec4(s.a > 1e-6 ? s.rgb / s.a : vec3(0.0), 1.0);
}
