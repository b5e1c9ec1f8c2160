// PassKit::supersample_edges: the texels edges.frag marked, listed row by
// row in column order, so that the list (and each texel's place in the
// packed pass that shades it) is the same from run to run whatever order
// the threads ran in. Step 0 counts each row's marks (one invocation per
// row), step 1 turns the counts into each row's first index and the total
// (one invocation: a few thousand rows), step 2 writes each row's texels
// from there. Entry k is texel (k % width, k / width) of u_list, which has
// the buffer's size, holding x | y << 16. A row's marks are bits, 32 texels
// to a word (edges.frag).
layout(local_size_x = 64) in;
layout(r32ui, binding = 0) uniform readonly uimage2D u_marks;
layout(r32ui, binding = 1) uniform writeonly uimage2D u_list;
layout(std430, binding = 0) buffer Rows {
  uint total;
  uint first[];
};
uniform int u_step;
void main() {
  ivec2 words = imageSize(u_marks);
  int width = imageSize(u_list).x;
  int y = int(gl_GlobalInvocationID.x);
  if (u_step == 1) {
    if (y != 0) return;
    uint sum = 0u;
    for (int r = 0; r < words.y; ++r) {
      uint n = first[r];
      first[r] = sum;
      sum += n;
    }
    total = sum;
    return;
  }
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
