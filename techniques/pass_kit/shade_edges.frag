// Reshades the texels edges.frag marked, packed: every fragment run is a
// marked texel (a pass over the buffer itself, stencil tested, runs whole
// 4x4 blocks wherever one texel in them is marked). Entries 16 b .. 16 b + 15
// of the list (edges_list.comp) fill the 4x4 block b, row by row, the blocks
// u_block_columns to a row: a block (llvmpipe's unit; a GPU's quads and
// warps alike) holds neighbouring entries, texels near each other in the
// buffer, whose shading takes similar paths. Four
// samples on a rotated grid in the texel, each mapped to the screen by the
// technique's foveate_map (the mapping file comes first, as for
// shade_main.frag), averaged in linear light. The count is a uniform (4) so
// that the loop is not unrolled: the scene's shading is compiled once, not
// four times. Neighbouring fragments are unrelated texels: a scene's
// screen-space derivatives mean nothing here.
#include "color.glsl"
#include "pass_kit/footprint.glsl"
uniform usampler2D u_edge_list;
uniform int u_edge_samples;
uniform int u_block_columns;
uniform int u_count;  // entries in the list; the last block's rest is not shaded
out vec4 o_color;
const vec2 kOffsets[4] =
    vec2[4](vec2(0.125, 0.375), vec2(0.375, -0.125), vec2(-0.125, -0.375), vec2(-0.375, 0.125));
void main() {
  ivec2 q = ivec2(gl_FragCoord.xy);
  int k = ((q.y >> 2) * u_block_columns + (q.x >> 2)) * 16 + (q.y & 3) * 4 + (q.x & 3);
  if (k >= u_count) {
    o_color = vec4(0.0);
    return;
  }
  int w = textureSize(u_edge_list, 0).x;
  uint e = texelFetch(u_edge_list, ivec2(k % w, k / w), 0).r;
  vec2 texel = vec2(float(e & 0xFFFFu), float(e >> 16)) + 0.5;
  vec3 sum = vec3(0.0);
#ifdef FOVEATE_FOOTPRINT
  // Four samples in the texel: half its spacing apart.
  foveate_footprint_px = 0.5 * foveate_spacing(texel, foveate_map(texel));
#endif
  for (int i = 0; i < u_edge_samples; ++i) {
    sum += foveate_linear(scene_shade(foveate_map(texel + kOffsets[i & 3])).rgb);
  }
  o_color = vec4(sum / float(u_edge_samples), 1.0);
}
