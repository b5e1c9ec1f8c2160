// First pass of the reconstruction (see filter.glsl): the horizontal
// Gaussian of the frame, as wide as at this pixel (region 0 rows like region
// 1: only the blend band and regions 1-3 read them). Pixels that no vertical
// pass will read are skipped.
#include "checkerboard/filter.glsl"
uniform sampler2D u_frame;
uniform float u_skip_radius;  // pixels nearer the gaze than this are not read
out vec4 o_color;
void main() {
  vec2 p = pattern_top_left(gl_FragCoord.xy);
  if (distance(p, u_gaze_top_left) < u_skip_radius) {
    o_color = vec4(0.0);
    return;
  }
  o_color = filter_axis(u_frame, ivec2(gl_FragCoord.xy), vec2(1.0, 0.0), filter_sigma(gl_FragCoord.xy));
}
