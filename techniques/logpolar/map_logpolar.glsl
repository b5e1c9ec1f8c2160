// The shading pass's mapping: a buffer texel, jittered by this frame's
// sub-texel offset (temporal antialiasing), to the screen position it
// samples. Texels inside the native disc or beyond the screen (plus a margin
// for filtering) are not shaded at all; the others shade the nearest pixel
// centre on the screen, so that no texel reads beyond the screen (a deferred
// scene's G-buffer is empty there: the dark rim it made).
#include "logpolar/mapping.glsl"
uniform vec2 u_lp_gaze;    // screen pixels, origin bottom-left
uniform float u_lp_L;      // log of the distance the buffer spans
uniform float u_lp_alpha;
uniform vec2 u_lp_buffer;  // w, h
uniform vec2 u_lp_jitter;  // texels
uniform vec4 u_lp_keep;    // x0, y0, x1, y1: texels mapping outside are not shaded
uniform vec2 u_lp_screen;  // W, H
uniform float u_lp_skip;   // texels mapping nearer the gaze are not shaded
vec2 foveate_map(vec2 frag) {
  vec2 p = lp_to_screen(frag + u_lp_jitter, u_lp_gaze, u_lp_L, u_lp_alpha, u_lp_buffer);
  if (distance(p, u_lp_gaze) < u_lp_skip || any(lessThan(p, u_lp_keep.xy)) ||
      any(greaterThan(p, u_lp_keep.zw))) {
    discard;
  }
  return clamp(p, vec2(0.5), u_lp_screen - 0.5);
}
