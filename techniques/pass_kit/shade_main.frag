// A shading pass: the technique's mapping gives the screen position, the
// scene shades it. No discard here, and no keep rectangle: on llvmpipe a
// shader that can discard is slower everywhere, even where it never discards
// (docs/performance.md). What a pass must not shade it leaves out with the
// cover it draws over (PassKit::shade).
#include "color.glsl"
#include "pass_kit/footprint.glsl"
out vec4 o_color;
void main() {
  vec2 p = foveate_map(gl_FragCoord.xy);
#ifdef FOVEATE_FOOTPRINT
  foveate_footprint_px = foveate_spacing(gl_FragCoord.xy, p);
#endif
  o_color = vec4(foveate_linear(scene_shade(p).rgb), 1.0);
}
