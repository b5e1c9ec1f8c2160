// A shading pass whose depth and stencil tests run before the shader, so that
// masked fragments are never shaded (checkerboard, lodmask). No discard here:
// a discard would make the driver test late.
#include "color.glsl"
layout(early_fragment_tests) in;
out vec4 o_color;
void main() { o_color = vec4(foveate_linear(scene_shade(foveate_map(gl_FragCoord.xy)).rgb), 1.0); }
