// A shading pass whose depth and stencil tests run before the shader, so that
// masked fragments are never shaded (checkerboard, lodmask). No discard here:
// a discard would make the driver test late.
#include "color.glsl"
#include "pass_kit/footprint.glsl"
layout(early_fragment_tests) in;
out vec4 o_color;
void main() {
  vec2 p = foveate_map(gl_FragCoord.xy);
#ifdef FOVEATE_FOOTPRINT
  foveate_footprint_px = foveate_spacing(gl_FragCoord.xy, p);
#endif
  o_color = vec4(foveate_linear(scene_shade(p).rgb), 1.0);
}
