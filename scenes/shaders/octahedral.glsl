// Unit normals in two numbers: the octahedron |x| + |y| + |z| = 1, its lower
// half folded out over the corners of [-1, 1]^2 (gbuffer.frag writes them,
// deferred_common.glsl reads them). The fold is its own inverse.
vec2 octahedral_fold(vec2 v) {
  return (1.0 - abs(v.yx)) * vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}
vec2 octahedral_encode(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  return n.z < 0.0 ? octahedral_fold(n.xy) : n.xy;
}
vec3 octahedral_decode(vec2 e) {
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = octahedral_fold(n.xy);
  return normalize(n);
}
