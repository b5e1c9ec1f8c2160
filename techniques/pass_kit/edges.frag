// PassKit::supersample_edges: marks for supersampling (bit x % 32 of word
// (x / 32, y) of u_marks, so that listing them reads a 32nd as much) the
// texels of a warped buffer whose linear luminance differs from their four
// neighbours' by more than u_edge of the brighter (a silhouette, a small
// object, a sharp highlight: where one sample per texel aliases).
// Neighbours are taken within the columns this pass covers (u_columns) and
// the rows in use (u_rows: the texture may have more); rows wrap where they
// are angles around the gaze (u_wrap_rows), else stop at the last. One not
// shaded this frame (alpha 0: the buffer is cleared) counts as the texel
// itself.
layout(r32ui, binding = 0) uniform coherent uimage2D u_marks;
uniform sampler2D u_buffer;
uniform float u_edge;
uniform vec2 u_columns;  // the first column and one past the last
uniform int u_wrap_rows;
uniform int u_rows;
const vec3 kLuma = vec3(0.2126, 0.7152, 0.0722);
float luma(ivec2 p, float own) {
  vec4 v = texelFetch(u_buffer, p, 0);
  return v.a > 0.5 ? dot(v.rgb, kLuma) : own;
}
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float c = dot(texelFetch(u_buffer, p, 0).rgb, kLuma);
  float l = luma(ivec2(max(p.x - 1, int(u_columns.x)), p.y), c);
  float r = luma(ivec2(min(p.x + 1, int(u_columns.y) - 1), p.y), c);
  int up = u_wrap_rows != 0 ? (p.y + 1) % u_rows : min(p.y + 1, u_rows - 1);
  int down = u_wrap_rows != 0 ? (p.y + u_rows - 1) % u_rows : max(p.y - 1, 0);
  float u = luma(ivec2(p.x, up), c);
  float d = luma(ivec2(p.x, down), c);
  float lo = min(c, min(min(l, r), min(u, d)));
  float hi = max(c, max(max(l, r), max(u, d)));
  if (hi - lo > u_edge * (hi + 0.02))
    imageAtomicOr(u_marks, ivec2(p.x >> 5, p.y), 1u << uint(p.x & 31));
}
