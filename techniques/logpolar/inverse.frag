// Screen <- kernel log-polar buffer, and the native disc around the gaze.
// Inside the disc (where the buffer would sample the screen at least as
// finely as its pixels) the screen shows native pixels; over a band beyond it
// they fade into the buffer's image. Second level of the two-level
// antialiasing (Meng et al.): a Gaussian over the buffer whose width, in
// buffer texels, grows from zero at the disc's edge to u_blur, so that on the
// screen it grows with eccentricity. Texels left out (alpha 0) get no weight.
// The buffer repeats along v, so there is no seam where the angle wraps around.
#include "logpolar/mapping.glsl"
uniform sampler2D u_buffer;  // the resolved buffer, premultiplied by alpha
uniform sampler2D u_fovea;   // native pixels of u_fovea_rect
uniform vec4 u_fovea_rect;   // x0, y0, w, h in screen pixels (origin bottom-left)
uniform int u_has_fovea;
uniform vec3 u_disc;  // native radius, blend band width, distance over which the blur grows
uniform vec2 u_lp_gaze;
uniform float u_lp_L;
uniform float u_lp_alpha;
uniform vec2 u_lp_buffer;
uniform float u_blur;  // Gaussian sigma in buffer texels, at full width
out vec4 o_color;

vec3 native_pixel() {
  return texelFetch(u_fovea, ivec2(gl_FragCoord.xy - u_fovea_rect.xy), 0).rgb;
}

void main() {
  float r = distance(gl_FragCoord.xy, u_lp_gaze);
  bool fovea = u_has_fovea != 0 && r < u_disc.x + u_disc.y;
  if (fovea && r <= u_disc.x) {
    o_color = vec4(native_pixel(), 1.0);
    return;
  }
  vec2 uv = lp_to_uv(gl_FragCoord.xy, u_lp_gaze, u_lp_L, u_lp_alpha);
  // The Gaussian over the texels -1, 0, 1 of each axis, as four bilinear
  // reads at (+-o, +-o) texels: o^2 is the 3-tap kernel's variance, so the
  // blur has the same width (separable; the weights need no exponential per
  // read). Near the disc's edge, sigma 0: one bilinear read.
  float sigma = u_blur * clamp((r - u_disc.x) / max(u_disc.z, 1.0), 0.0, 1.0);
  float w1 = sigma > 0.0 ? exp(-0.5 / (sigma * sigma)) : 0.0;
  float o = sqrt(2.0 * w1 / (1.0 + 2.0 * w1));
  vec2 texel = 1.0 / u_lp_buffer;
  vec4 acc = vec4(0.0);
  if (o < 1e-3) {
    acc = texture(u_buffer, vec2(clamp(uv.x, 0.5 * texel.x, 1.0 - 0.5 * texel.x), uv.y));
  } else {
    for (int j = -1; j <= 1; j += 2) {
      for (int i = -1; i <= 1; i += 2) {
        vec2 q = uv + o * vec2(float(i), float(j)) * texel;
        q.x = clamp(q.x, 0.5 * texel.x, 1.0 - 0.5 * texel.x);
        acc += texture(u_buffer, q);
      }
    }
  }
  vec3 c = acc.a > 1e-6 ? acc.rgb / acc.a : vec3(0.0);
  if (fovea) c = mix(native_pixel(), c, smoothstep(u_disc.x, u_disc.x + u_disc.y, r));
  o_color = vec4(c, 1.0);
}
