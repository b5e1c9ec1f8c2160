// Screen <- kernel log-polar buffer: u = K^-1(log r / L) w, v = angle / 2 pi h,
// with K^-1(x) = x^(1/alpha). Second level of the antialiasing: a Gaussian of
// fixed width in buffer texels, i.e. growing with eccentricity on screen. The
// buffer repeats along v, so there is no seam where the angle wraps around.
uniform sampler2D u_buffer;
uniform vec2 u_lp_gaze;
uniform float u_lp_L;
uniform float u_lp_alpha;
uniform vec2 u_lp_buffer;
uniform float u_blur;  // Gaussian sigma in buffer texels
out vec4 o_color;

void main() {
  vec2 d = gl_FragCoord.xy - u_lp_gaze;
  float r = max(length(d), 1.0);
  float u = pow(clamp(log(r) / u_lp_L, 0.0, 1.0), 1.0 / u_lp_alpha);
  float a = atan(d.y, d.x);
  if (a < 0.0) a += 6.28318530718;
  vec2 uv = vec2(u, a / 6.28318530718);
  if (u_blur <= 0.0) {
    o_color = vec4(texture(u_buffer, uv).rgb, 1.0);
    return;
  }
  vec2 texel = 1.0 / u_lp_buffer;
  vec3 acc = vec3(0.0);
  float wsum = 0.0;
  for (int j = -1; j <= 1; ++j) {
    for (int i = -1; i <= 1; ++i) {
      vec2 o = vec2(float(i), float(j));
      float w = exp(-dot(o, o) / (2.0 * u_blur * u_blur));
      vec2 q = uv + o * texel;
      q.x = clamp(q.x, 0.5 * texel.x, 1.0 - 0.5 * texel.x);
      acc += w * texture(u_buffer, q).rgb;
      wsum += w;
    }
  }
  o_color = vec4(acc / wsum, 1.0);
}
