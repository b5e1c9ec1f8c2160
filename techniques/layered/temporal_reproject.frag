// Temporal resolve of a layer with scene depth (Guenter et al. 4.2, after
// Nehab et al.'s reverse reprojection): the world point seen at each pixel of
// the unjittered grid, from the scene's G-buffer, moves on screen by the
// difference of its projections under the current and the previous camera;
// the history is read where it was.
#include "layered/temporal_common.glsl"
uniform mat4 u_view_proj;
uniform mat4 u_prev_view_proj;
uniform vec2 u_frame_size;  // full frame in pixels
void main() {
  vec2 size = vec2(textureSize(u_sample, 0));
  vec2 screen = u_rect.xy + gl_FragCoord.xy * (u_rect.zw / size);
  vec4 p = vec4(scene_world_position(screen), 1.0);
  vec4 now = u_view_proj * p, before = u_prev_view_proj * p;
  vec2 prev_screen = vec2(-1e9);  // behind either camera: no history
  if (now.w > 0.0 && before.w > 0.0)
    prev_screen = screen + (before.xy / before.w - now.xy / now.w) * 0.5 * u_frame_size;
  o_color = foveate_temporal(prev_screen);
}
