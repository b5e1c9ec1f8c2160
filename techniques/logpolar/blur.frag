// Second level of the two-level antialiasing (Meng et al.), in the buffer:
// a Gaussian whose width, in buffer texels, grows from zero at the native
// disc's edge to u_blur, so that on the screen it grows with eccentricity.
// The width depends only on the buffer column (the distance from the gaze),
// so it is applied here once per texel, and the inverse mapping reads the
// result once per screen pixel. Texels left out (alpha 0) get no weight: the
// buffer is premultiplied by alpha and the inverse mapping divides by it.
// The buffer repeats along v, so there is no seam where the angle wraps.
uniform sampler2D u_buffer;
uniform vec3 u_disc;  // native radius, blend band width, distance over which the blur grows
uniform float u_lp_L;
uniform float u_lp_alpha;
uniform vec2 u_lp_buffer;
uniform float u_blur;  // Gaussian sigma in buffer texels, at full width
out vec4 o_color;
void main() {
  vec2 texel = 1.0 / u_lp_buffer;
  vec2 uv = gl_FragCoord.xy * texel;
  float r = exp(u_lp_L * pow(uv.x, u_lp_alpha));  // this column's distance from the gaze
  // The Gaussian over the texels -1, 0, 1 of each axis, as four bilinear
  // reads at (+-o, +-o) texels: o^2 is the 3-tap kernel's variance, so the
  // blur has the same width (separable; the weights need no exponential per
  // read). Near the disc's edge, sigma 0: the texel itself.
  float sigma = u_blur * clamp((r - u_disc.x) / max(u_disc.z, 1.0), 0.0, 1.0);
  float w1 = sigma > 0.0 ? exp(-0.5 / (sigma * sigma)) : 0.0;
  // The inverse mapping's bilinear read of the result interpolates between
  // texel centres, which widens the blur by about a bilinear read's own
  // variance (1/6 texel^2 per axis): taken off here where there is as much.
  float o = sqrt(max(2.0 * w1 / (1.0 + 2.0 * w1) - 1.0 / 6.0, 0.0));
  vec4 acc = vec4(0.0);
  for (int j = -1; j <= 1; j += 2) {
    for (int i = -1; i <= 1; i += 2) {
      vec2 q = uv + o * vec2(float(i), float(j)) * texel;
      q.x = clamp(q.x, 0.5 * texel.x, 1.0 - 0.5 * texel.x);
      acc += texture(u_buffer, q);
    }
  }
  o_color = 0.25 * acc;
}
