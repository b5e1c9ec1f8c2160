// PassKit::supersample_edges: the texels edges.frag marked, listed row by
// row in column order, so that the list (and each texel's place in the
// packed pass that shades it) is the same from run to run whatever order
// the threads ran in. Step 0 counts each row's marks (one invocation per
// row), step 1 turns the counts into each row's first index (one workgroup:
// each invocation sums a run of rows, then a scan over the runs), step 2
// writes each row's texels from there. Entry k is texel (k % width,
// k / width) of u_list, which has the buffer's size, holding x | y << 16. A
// row's marks are bits, 32 texels to a word (edges.frag).
//
// Step 1 also writes what the passes after it need to know of the total, so
// that a GPU runs them without the CPU reading the total back (a read waits
// for every pass before it): the indirect dispatch of edges_scatter.comp (an
// invocation per entry, 64 to a group) and the indirect draw of the packed
// pass over its 4x4 blocks (packed_rects.vert: one rectangle of whole rows
// of u_block_columns blocks, one of the rest).
#include "pass_kit/edges_rows.glsl"
layout(local_size_x = 64) in;
layout(r32ui, binding = 0) uniform readonly uimage2D u_marks;
layout(r32ui, binding = 1) uniform writeonly uimage2D u_list;
uniform int u_step;
uniform int u_block_columns;
shared uint s_sum[64];

void write_header(uint n) {
  total = n;
  dispatch_x = (n + 63u) / 64u;
  dispatch_y = 1u;
  dispatch_z = 1u;
  uint blocks = (n + 15u) / 16u, columns = uint(u_block_columns);
  uint full = blocks / columns, rest = blocks % columns;
  int rects = 0;
  if (full > 0u) cover[rects++] = ivec4(0, 0, int(4u * columns), int(4u * full));
  if (rest > 0u) cover[rects++] = ivec4(0, int(4u * full), int(4u * rest), int(4u * full + 4u));
  // DrawArraysIndirectCommand: a quad of 6 vertices per rectangle.
  draw_command = uvec4(6u, uint(rects), 0u, 0u);
}

void main() {
  ivec2 words = imageSize(u_marks);
  int width = imageSize(u_list).x;
  if (u_step == 1) {
    // Dispatched as one group: the scan's barriers are reached by all.
    uint t = gl_LocalInvocationID.x;
    int run = (words.y + 63) / 64;
    int r0 = min(words.y, int(t) * run), r1 = min(words.y, r0 + run);
    uint own = 0u;
    for (int r = r0; r < r1; ++r) own += first[r];
    s_sum[t] = own;
    memoryBarrierShared();
    barrier();
    for (uint d = 1u; d < 64u; d <<= 1u) {
      uint before = t >= d ? s_sum[t - d] : 0u;
      barrier();
      s_sum[t] += before;
      memoryBarrierShared();
      barrier();
    }
    uint sum = s_sum[t] - own;
    for (int r = r0; r < r1; ++r) {
      uint n = first[r];
      first[r] = sum;
      sum += n;
    }
    if (t == 63u) write_header(s_sum[63]);
    return;
  }
  int y = int(gl_GlobalInvocationID.x);
  if (y >= words.y) return;
  uint k = u_step == 0 ? 0u : first[y];
  for (int i = 0; i < words.x; ++i) {
    uint bits = imageLoad(u_marks, ivec2(i, y)).r;
    if (u_step == 0) {
      k += uint(bitCount(bits));
      continue;
    }
    while (bits != 0u) {
      int b = findLSB(bits);
      bits &= bits - 1u;
      imageStore(u_list, ivec2(int(k) % width, int(k) / width),
                 uvec4(uint(i * 32 + b) | (uint(y) << 16)));
      ++k;
    }
  }
  if (u_step == 0) first[y] = k;
}
