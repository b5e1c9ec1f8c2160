// A shading pass: the technique's mapping gives the screen position, the
// scene shades it. Positions outside u_keep_rect (screen bounds grown by a
// margin for filtering) are not shaded at all.
#include "color.glsl"
uniform vec4 u_keep_rect;  // x0, y0, x1, y1; empty = keep everything
out vec4 o_color;
void main() {
  vec2 p = foveate_map(gl_FragCoord.xy);
  if (u_keep_rect.z > u_keep_rect.x &&
      (p.x < u_keep_rect.x || p.y < u_keep_rect.y || p.x > u_keep_rect.z || p.y > u_keep_rect.w)) {
    discard;
  }
  o_color = vec4(foveate_linear(scene_shade(p).rgb), 1.0);
}
