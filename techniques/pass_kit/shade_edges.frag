// Reshades the texels edges.frag marked, packed: every fragment run is a
// marked texel (a pass over the buffer itself, stencil tested, runs whole
// 4x4 blocks wherever one texel in them is marked). Entries 16 b .. 16 b + 15
// of the list (edges_list.comp) fill the 4x4 block b, row by row, the blocks
// u_block_columns to a row: a block (llvmpipe's unit; a GPU's quads and
// warps alike) holds neighbouring entries, texels near each other in the
// buffer, whose shading takes similar paths. The samples, each mapped to
// the screen by the technique's foveate_map (the mapping file comes first,
// as for shade_main.frag), are averaged in linear light: u_edge_samples = 4
// on a rotated grid in the texel; or 2 on its diagonal, a third of the
// texel from its centre, with the centre sample the texel already holds
// (u_centre, the buffer's copy): three samples, one in each third of the
// texel across and down, for half the shading. The count is a uniform so
// that the loop is not unrolled: the scene's shading is compiled once.
// Neighbouring fragments are unrelated texels: a scene's screen-space
// derivatives mean nothing here.
#include "color.glsl"
#include "pass_kit/footprint.glsl"
#include "pass_kit/edges_rows.glsl"
uniform usampler2D u_edge_list;
uniform int u_edge_samples;
uniform int u_block_columns;
uniform sampler2D u_centre;
out vec4 o_color;
const vec2 kGrid[4] =
    vec2[4](vec2(0.125, 0.375), vec2(0.375, -0.125), vec2(-0.125, -0.375), vec2(-0.375, 0.125));
const vec2 kDiagonal[2] = vec2[2](vec2(-1.0 / 3.0, 1.0 / 3.0), vec2(1.0 / 3.0, -1.0 / 3.0));
void main() {
  ivec2 q = ivec2(gl_FragCoord.xy);
  int k = ((q.y >> 2) * u_block_columns + (q.x >> 2)) * 16 + (q.y & 3) * 4 + (q.x & 3);
  if (k >= int(total)) {  // the last block's rest
    o_color = vec4(0.0);
    return;
  }
  int w = textureSize(u_edge_list, 0).x;
  uint e = texelFetch(u_edge_list, ivec2(k % w, k / w), 0).r;
  vec2 texel = vec2(float(e & 0xFFFFu), float(e >> 16)) + 0.5;
  bool grid = u_edge_samples == 4;
  // The centre's sample, decoded to linear light by the sampler where the
  // buffer stores sRGB.
  vec3 sum = grid ? vec3(0.0) : texelFetch(u_centre, ivec2(texel), 0).rgb;
  float n = grid ? 4.0 : 3.0;
#ifdef FOVEATE_FOOTPRINT
  // n samples in the texel: each stands for 1/n of its area.
  foveate_footprint_px = foveate_spacing(texel, foveate_map(texel)) / sqrt(n);
#endif
  for (int i = 0; i < u_edge_samples; ++i) {
    vec2 offset = grid ? kGrid[i & 3] : kDiagonal[i & 1];
    sum += foveate_linear(scene_shade(foveate_map(texel + offset)).rgb);
  }
  o_color = vec4(sum / n, 1.0);
}
