// Screen <- kernel log-polar buffer (blurred, see blur.frag), and the native
// disc around the gaze: what the inverse mapping's regions read.
#include "logpolar/mapping.glsl"
uniform sampler2D u_buffer;  // the blurred buffer, premultiplied by alpha
uniform sampler2D u_fovea;   // native pixels of u_fovea_rect
uniform vec4 u_fovea_rect;   // x0, y0, w, h in screen pixels (origin bottom-left)
uniform vec2 u_lp_gaze;
uniform float u_lp_L;
uniform float u_lp_alpha;
uniform vec2 u_lp_buffer;

vec3 native_pixel() {
  return texelFetch(u_fovea, ivec2(gl_FragCoord.xy - u_fovea_rect.xy), 0).rgb;
}

// One bilinear read of the buffer at this pixel, divided by its coverage.
vec3 buffer_colour() {
  vec2 uv = lp_to_uv(gl_FragCoord.xy, u_lp_gaze, u_lp_L, u_lp_alpha);
  float half_texel = 0.5 / u_lp_buffer.x;
  vec4 s = texture(u_buffer, vec2(clamp(uv.x, half_texel, 1.0 - half_texel), uv.y));
  return s.a > 1e-6 ? s.rgb / s.a : vec3(0.0);
}
