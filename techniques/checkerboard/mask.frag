// Writes the stencil mask of one region: its kept pixels get the region's
// stencil value; dropped quads and other regions are discarded.
#include "checkerboard/pattern.glsl"
uniform int u_region;
out vec4 o_color;
void main() {
  if (pattern_region(gl_FragCoord.xy) != u_region || !pattern_kept(gl_FragCoord.xy)) discard;
  o_color = vec4(0.0);
}
