// PassKit::supersample_edges: each listed texel's packed shading
// (shade_edges.frag's block layout) stored back into the buffer, one
// invocation per entry (the total from edges_list.comp's head: the
// dispatch may be sized by the GPU alone). An sRGB-encoded buffer is written through a view of
// its bytes as RGBA8 (image stores do not encode), so the colour is encoded
// here.
#include "color.glsl"
#include "pass_kit/edges_rows.glsl"
layout(local_size_x = 64) in;
layout(r32ui, binding = 1) uniform readonly uimage2D u_list;
layout(binding = 2) uniform writeonly image2D u_buffer;
uniform sampler2D u_shaded;
uniform int u_block_columns;
uniform int u_srgb;
void main() {
  int k = int(gl_GlobalInvocationID.x);
  if (k >= int(total)) return;
  int w = imageSize(u_list).x;
  uint e = imageLoad(u_list, ivec2(k % w, k / w)).r;
  int b = k >> 4, i = k & 15;
  ivec2 block = ivec2(b % u_block_columns, b / u_block_columns) * 4;
  vec4 c = texelFetch(u_shaded, block + ivec2(i & 3, i >> 2), 0);
  if (u_srgb != 0) c.rgb = foveate_srgb(c.rgb);
  imageStore(u_buffer, ivec2(int(e & 0xFFFFu), int(e >> 16)), c);
}
