// Temporal antialiasing of the log-polar buffer (temporal_common.glsl) with
// scene depth: the texel's world point, from the scene's G-buffer, is
// projected with the previous frame's camera (reverse reprojection).
#include "logpolar/temporal_common.glsl"
uniform mat4 u_prev_view_proj;
void main() {
  vec4 clip = u_prev_view_proj * vec4(scene_world_position(lp_texel_screen()), 1.0);
  bool known = clip.w > 0.0;
  o_color = lp_temporal(known ? (clip.xy / clip.w * 0.5 + 0.5) * u_lp_screen : vec2(0.0), known);
}
