// The buffer's shading with several samples per texel, averaged in linear
// light: a box prefilter over the texel's footprint, which point sampling
// at half the MAR lacks (small objects and silhouettes alias and pop). The
// positions are a rotated grid in the texel (2: its diagonal), or for 9 and
// 16 a 3x3 or 4x4 grid of equal cells (the texel's area average), mapped to
// the screen like the texel's centre (map_warp.glsl).
#include "color.glsl"
#include "marwarp/map_warp.glsl"
#include "pass_kit/footprint.glsl"
uniform int u_samples;  // 2, 4, 9 or 16
out vec4 o_color;
const vec2 kOffsets4[4] =
    vec2[4](vec2(0.125, 0.375), vec2(0.375, -0.125), vec2(-0.125, -0.375), vec2(-0.375, 0.125));
const vec2 kOffsets2[2] = vec2[2](vec2(0.25, 0.25), vec2(-0.25, -0.25));
void main() {
  vec3 sum = vec3(0.0);
#ifdef FOVEATE_FOOTPRINT
  // u_samples in the texel: its spacing over their square root.
  foveate_footprint_px =
      foveate_spacing(gl_FragCoord.xy, foveate_map(gl_FragCoord.xy)) / sqrt(float(u_samples));
#endif
  int n = u_samples == 9 ? 3 : 4;  // the grid's side for 9 and 16
  // A loop with a uniform bound: llvmpipe runs only as many samples as asked.
  for (int i = 0; i < u_samples; ++i) {
    vec2 o = u_samples == 4   ? kOffsets4[i]
             : u_samples == 2 ? kOffsets2[i & 1]
                              : (vec2(float(i % n), float(i / n)) + 0.5) / float(n) - 0.5;
    sum += foveate_linear(scene_shade(foveate_map(gl_FragCoord.xy + o)).rgb);
  }
  o_color = vec4(sum / float(u_samples), 1.0);
}
