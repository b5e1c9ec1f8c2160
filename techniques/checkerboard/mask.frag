// Writes the stencil mask: the pixels the pattern keeps (any region) get the
// pass's reference value; dropped quads are discarded (stencil stays 0).
#include "checkerboard/pattern.glsl"
out vec4 o_color;
void main() {
  if (!pattern_kept(gl_FragCoord.xy)) discard;
  o_color = vec4(0.0);
}
