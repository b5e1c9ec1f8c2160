// Writes a reshaded texel's packed shading (shade_edges.frag) back into the
// buffer, at the texel its point covers (edges_scatter.vert).
uniform sampler2D u_shaded;
flat in ivec2 v_entry;
out vec4 o_color;
void main() { o_color = texelFetch(u_shaded, v_entry, 0); }
