// Temporal reverse reprojection of one layer (screen space): the previous
// result is resampled at this frame's (jittered) sample positions, clamped to
// the current 3x3 neighbourhood so that disoccluded or changed samples are
// rejected, and blended with the current samples.
uniform sampler2D u_current;
uniform sampler2D u_history;
uniform vec4 u_rect;       // this frame's screen rectangle x0, y0, w, h
uniform vec4 u_prev_rect;  // the history's screen rectangle
uniform float u_history_weight;
out vec4 o_color;
void main() {
  ivec2 size = textureSize(u_current, 0);
  ivec2 ip = ivec2(gl_FragCoord.xy);
  vec3 c = texelFetch(u_current, ip, 0).rgb;
  if (u_history_weight <= 0.0) {
    o_color = vec4(c, 1.0);
    return;
  }
  vec3 lo = c, hi = c;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      vec3 n = texelFetch(u_current, clamp(ip + ivec2(dx, dy), ivec2(0), size - 1), 0).rgb;
      lo = min(lo, n);
      hi = max(hi, n);
    }
  }
  vec2 screen = u_rect.xy + gl_FragCoord.xy / vec2(size) * u_rect.zw;
  vec2 huv = (screen - u_prev_rect.xy) / u_prev_rect.zw;
  if (any(lessThan(huv, vec2(0.0))) || any(greaterThan(huv, vec2(1.0)))) {
    o_color = vec4(c, 1.0);
    return;
  }
  vec3 h = clamp(texture(u_history, huv).rgb, lo, hi);
  o_color = vec4(mix(c, h, u_history_weight), 1.0);
}
