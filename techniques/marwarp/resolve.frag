// The resolve where the native disc fades into the buffer: native pixels
// inside the disc, fading into the buffer over a band beyond it. Drawn over
// the disc and its band only when the target can be split
// (resolve_fovea.frag inside, resolve_outer.frag beyond), over the whole
// screen when not.
#include "marwarp/resolve_common.glsl"
uniform vec2 u_disc;  // native radius, blend band width
layout(early_fragment_tests) in;
out vec4 o_color;
void main() {
  float r = distance(gl_FragCoord.xy, u_warp_gaze);
  if (r <= u_disc.x) {
    o_color = vec4(native_pixel(), 1.0);
    return;
  }
  vec3 c = buffer_colour();
  if (r < u_disc.x + u_disc.y) c = mix(native_pixel(), c, smoothstep(u_disc.x, u_disc.x + u_disc.y, r));
  o_color = vec4(c, 1.0);
}
