// Kernel log-polar mapping (Meng et al. 2018), both ways, with K(x) = x^alpha:
//   buffer -> screen: r = exp(L K(u / w)), angle = v 2 pi / h;
//   screen -> buffer: u = K^-1(log r / L) w, v = angle / (2 pi) h.
// Screen positions are pixels (origin bottom-left), buffer positions texels.
const float LP_TWO_PI = 6.28318530718;

vec2 lp_to_screen(vec2 buffer_px, vec2 gaze, float L, float alpha, vec2 size) {
  float r = exp(L * pow(max(buffer_px.x / size.x, 0.0), alpha));
  float a = buffer_px.y * LP_TWO_PI / size.y;
  return gaze + r * vec2(cos(a), sin(a));
}

// Normalized buffer coordinates (u / w, v / h) of a screen position.
vec2 lp_to_uv(vec2 screen, vec2 gaze, float L, float alpha) {
  vec2 d = screen - gaze;
  float r = max(length(d), 1.0);
  float u = pow(clamp(log(r) / L, 0.0, 1.0), 1.0 / alpha);
  float a = atan(d.y, d.x);
  if (a < 0.0) a += LP_TWO_PI;
  return vec2(u, a / LP_TWO_PI);
}
