// Writes the stencil mask: fragments of dropped quads are discarded.
#include "checkerboard/pattern.glsl"
out vec4 o_color;
void main() {
  if (!pattern_kept(gl_FragCoord.xy)) discard;
  o_color = vec4(0.0);
}
