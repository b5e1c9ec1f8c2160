// Writes the whole stencil mask in one pass where the driver can export
// stencil values from a shader: region k + 1 for kept pixels of region k;
// dropped quads are discarded (stencil stays 0).
#extension GL_ARB_shader_stencil_export : require
#include "checkerboard/pattern.glsl"
out vec4 o_color;
void main() {
  if (!pattern_kept(gl_FragCoord.xy)) discard;
  gl_FragStencilRefARB = pattern_region(gl_FragCoord.xy) + 1;
  o_color = vec4(0.0);
}
