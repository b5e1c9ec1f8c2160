// The shading pass's mapping: a buffer texel's centre to the screen position
// it samples, clamped to the nearest pixel centre on the screen (a texel
// beyond the edge, shaded for the resolve's filter, repeats the edge: a
// deferred scene's G-buffer is empty beyond it).
#include "marwarp/warp.glsl"
uniform vec2 u_warp_screen;  // W, H
vec2 foveate_map(vec2 frag) { return clamp(warp_to_screen(frag), vec2(0.5), u_warp_screen - 0.5); }
