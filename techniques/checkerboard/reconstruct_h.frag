// Reconstruction, passes 2 and 3 (see filter.glsl): the Gaussian along one
// axis at 1/f resolution, as wide as at this block's full-resolution centre
// (region 0 blocks like region 1: only the blend band and regions 1-3 read
// them). Blocks that no later pass reads are skipped.
#include "checkerboard/filter.glsl"
uniform sampler2D u_input;
uniform vec2 u_axis;
uniform float u_skip_radius;  // full-resolution pixels nearer the gaze than this are not read
out vec4 o_color;
void main() {
  vec2 full = u_scale * gl_FragCoord.xy;
  if (distance(pattern_top_left(full), u_gaze_top_left) < u_skip_radius) {
    o_color = vec4(0.0);
    return;
  }
  o_color = filter_axis(u_input, ivec2(gl_FragCoord.xy), u_axis, scaled_sigma(filter_sigma(full)));
}
