// PassKit::supersample_edges: one point per listed texel (edges_list.comp),
// placed on that texel of the buffer, carrying where its packed shading is.
uniform usampler2D u_edge_list;
uniform vec2 u_buffer_size;
uniform int u_block_columns;  // shade_edges.frag's layout
flat out ivec2 v_entry;
void main() {
  int w = textureSize(u_edge_list, 0).x;
  int k = gl_VertexID, b = k >> 4, i = k & 15;
  v_entry = ivec2((b % u_block_columns) * 4 + (i & 3), (b / u_block_columns) * 4 + (i >> 2));
  uint e = texelFetch(u_edge_list, ivec2(k % w, k / w), 0).r;
  vec2 texel = vec2(float(e & 0xFFFFu), float(e >> 16)) + 0.5;
  gl_Position = vec4(texel / u_buffer_size * 2.0 - 1.0, 0.0, 1.0);
}
