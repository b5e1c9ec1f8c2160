// First level of the two-level antialiasing: temporal antialiasing in the
// log-polar buffer. Each frame's samples are jittered by a sub-texel offset;
// the previous resolved buffer is resampled where this texel's screen point
// was (through the previous gaze's mapping), clamped to this frame's 3x3
// neighbourhood (rejecting disocclusions and changes) and blended in. Alpha
// marks shaded texels (1) and texels left out (0: the native disc, beyond the
// screen); colour is premultiplied by it, so bilinear reads stay exact.
#include "logpolar/mapping.glsl"
uniform sampler2D u_current;
uniform sampler2D u_history;
uniform vec2 u_lp_gaze;
uniform float u_lp_L;
uniform float u_lp_alpha;
uniform vec2 u_lp_buffer;
uniform vec2 u_lp_screen;
uniform vec3 u_prev_mapping;  // the history's gaze (x, y) and L
uniform float u_history_weight;
out vec4 o_color;

// The screen point this texel's centre samples (clamped as the shading clamps it).
vec2 lp_texel_screen() {
  vec2 p = lp_to_screen(gl_FragCoord.xy, u_lp_gaze, u_lp_L, u_lp_alpha, u_lp_buffer);
  return clamp(p, vec2(0.5), u_lp_screen - 0.5);
}

// Resolves this texel given where its point was on the previous frame's screen.
vec4 lp_temporal(vec2 prev_screen, bool known) {
  ivec2 size = textureSize(u_current, 0);
  ivec2 ip = ivec2(gl_FragCoord.xy);
  vec4 c = texelFetch(u_current, ip, 0);
  if (c.a < 0.5) return vec4(0.0);
  if (u_history_weight <= 0.0 || !known) return vec4(c.rgb, 1.0);
  vec3 lo = c.rgb, hi = c.rgb;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = ivec2(clamp(ip.x + dx, 0, size.x - 1), (ip.y + dy + size.y) % size.y);
      vec4 n = texelFetch(u_current, q, 0);
      if (n.a < 0.5) continue;
      lo = min(lo, n.rgb);
      hi = max(hi, n.rgb);
    }
  }
  vec4 h = texture(u_history, lp_to_uv(prev_screen, u_prev_mapping.xy, u_prev_mapping.z, u_lp_alpha));
  if (h.a < 0.5) return vec4(c.rgb, 1.0);
  return vec4(mix(c.rgb, clamp(h.rgb / h.a, lo, hi), u_history_weight), 1.0);
}
