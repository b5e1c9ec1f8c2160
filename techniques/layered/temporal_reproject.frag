// Temporal reverse reprojection of one layer with scene depth (Guenter et
// al. 4.2, after Nehab et al.): each sample's world point, from the scene's
// G-buffer, is projected with the previous frame's camera into the previous
// result; the history found there is clamped to the current 3x3
// neighbourhood (rejecting disoccluded samples) and blended in.
uniform sampler2D u_current;
uniform sampler2D u_history;
uniform vec4 u_rect;        // this frame's screen rectangle x0, y0, w, h
uniform vec4 u_prev_rect;   // the history's screen rectangle
uniform mat4 u_prev_view_proj;
uniform vec2 u_frame_size;  // full frame in pixels
uniform float u_history_weight;
out vec4 o_color;
void main() {
  ivec2 size = textureSize(u_current, 0);
  ivec2 ip = ivec2(gl_FragCoord.xy);
  vec3 c = texelFetch(u_current, ip, 0).rgb;
  vec3 lo = c, hi = c;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      vec3 n = texelFetch(u_current, clamp(ip + ivec2(dx, dy), ivec2(0), size - 1), 0).rgb;
      lo = min(lo, n);
      hi = max(hi, n);
    }
  }
  vec2 screen = u_rect.xy + gl_FragCoord.xy * (u_rect.zw / vec2(size));
  vec4 clip = u_prev_view_proj * vec4(scene_world_position(screen), 1.0);
  if (clip.w <= 0.0) {
    o_color = vec4(c, 1.0);
    return;
  }
  vec2 prev_screen = (clip.xy / clip.w * 0.5 + 0.5) * u_frame_size;
  vec2 huv = (prev_screen - u_prev_rect.xy) / u_prev_rect.zw;
  if (any(lessThan(huv, vec2(0.0))) || any(greaterThan(huv, vec2(1.0)))) {
    o_color = vec4(c, 1.0);
    return;
  }
  vec3 h = clamp(texture(u_history, huv).rgb, lo, hi);
  o_color = vec4(mix(c, h, u_history_weight), 1.0);
}
