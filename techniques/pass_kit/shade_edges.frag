// Reshades the texels edges.frag marked (stencil test before the shader:
// the others are never run) with four samples on a rotated grid in the
// texel, each mapped to the screen by the technique's foveate_map (the
// mapping file comes first, as for shade_main.frag), averaged in linear
// light. The count is a uniform (4) so that the loop is not unrolled: the
// scene's shading is compiled once, not four times.
#include "color.glsl"
layout(early_fragment_tests) in;
uniform int u_edge_samples;
out vec4 o_color;
const vec2 kOffsets[4] =
    vec2[4](vec2(0.125, 0.375), vec2(0.375, -0.125), vec2(-0.125, -0.375), vec2(-0.375, 0.125));
void main() {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < u_edge_samples; ++i) {
    sum += foveate_linear(scene_shade(foveate_map(gl_FragCoord.xy + kOffsets[i & 3])).rgb);
  }
  o_color = vec4(sum / float(u_edge_samples), 1.0);
}
