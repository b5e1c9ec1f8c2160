// The shading pass's mapping: a buffer texel, jittered by this frame's
// sub-texel offset (temporal antialiasing), to the screen position it
// samples, clamped to the nearest pixel centre on the screen, so that no
// texel reads beyond the screen (a deferred scene's G-buffer is empty there:
// the dark rim it made). The texels inside the native disc or far beyond the
// screen are not drawn at all (the pass's cover, log_polar_cover); the few
// the cover's bands take in besides are shaded at their clamped positions.
#include "logpolar/mapping.glsl"
uniform vec2 u_lp_gaze;    // screen pixels, origin bottom-left
uniform float u_lp_L;      // log of the distance the buffer spans
uniform float u_lp_alpha;
uniform vec2 u_lp_buffer;  // w, h
uniform vec2 u_lp_jitter;  // texels
uniform vec2 u_lp_screen;  // W, H
vec2 foveate_map(vec2 frag) {
  vec2 p = lp_to_screen(frag + u_lp_jitter, u_lp_gaze, u_lp_L, u_lp_alpha, u_lp_buffer);
  return clamp(p, vec2(0.5), u_lp_screen - 0.5);
}
