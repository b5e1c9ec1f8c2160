// Kernel log-polar mapping, buffer -> screen (Meng et al. 2018):
//   r = exp(L K(u / w)), angle = v 2 pi / h, K(x) = x^alpha.
uniform vec2 u_lp_gaze;    // screen pixels, origin bottom-left
uniform float u_lp_L;      // log(sqrt(W^2 + H^2))
uniform float u_lp_alpha;
uniform vec2 u_lp_buffer;  // w, h
vec2 foveate_map(vec2 frag) {
  float r = exp(u_lp_L * pow(frag.x / u_lp_buffer.x, u_lp_alpha));
  float a = frag.y * 6.28318530718 / u_lp_buffer.y;
  return u_lp_gaze + r * vec2(cos(a), sin(a));
}
