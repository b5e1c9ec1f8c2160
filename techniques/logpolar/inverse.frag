// Inverse mapping where the native disc fades into the buffer's image: native
// pixels inside the disc (where the buffer would sample the screen at least
// as finely as its pixels), fading into the buffer over a band beyond it.
// Drawn over the disc and its band only when the target can be split
// (inverse_fovea.frag inside, inverse_outer.frag beyond), over the whole
// screen when not.
#include "logpolar/inverse_common.glsl"
uniform int u_has_fovea;
uniform vec2 u_disc;  // native radius, blend band width
layout(early_fragment_tests) in;
out vec4 o_color;
void main() {
  float r = distance(gl_FragCoord.xy, u_lp_gaze);
  bool fovea = u_has_fovea != 0 && r < u_disc.x + u_disc.y;
  if (fovea && r <= u_disc.x) {
    o_color = vec4(native_pixel(), 1.0);
    return;
  }
  vec3 c = buffer_colour();
  if (fovea) c = mix(native_pixel(), c, smoothstep(u_disc.x, u_disc.x + u_disc.y, r));
  o_color = vec4(c, 1.0);
}
