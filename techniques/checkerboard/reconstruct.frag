// Fills dropped quads from shaded neighbours. Coverage is explicit (alpha = 1
// where shaded), so black shaded pixels count as valid. As in Silvera's
// scheme: with shaded pixels on both sides along x and y, the two linear
// interpolations are averaged (regions 1 and 2); otherwise the diagonals are
// used (the bottom-right quad of region 3), then any single direction.
uniform sampler2D u_frame;
uniform int u_block;
out vec4 o_color;

ivec2 g_size;

bool fetch(ivec2 p, out vec3 c) {
  if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, g_size))) return false;
  vec4 t = texelFetch(u_frame, p, 0);
  c = t.rgb;
  return t.a > 0.5;
}

// Nearest shaded pixel from p along direction d within 2 blocks: colour and distance.
bool probe(ivec2 p, ivec2 d, out vec3 c, out float dist) {
  for (int k = 1; k <= 2 * u_block; ++k) {
    if (fetch(p + d * k, c)) {
      dist = float(k);
      return true;
    }
  }
  return false;
}

bool pair_interp(ivec2 p, ivec2 d, out vec3 c) {
  vec3 a, b;
  float da, db;
  bool ha = probe(p, d, a, da), hb = probe(p, -d, b, db);
  if (ha && hb) {
    c = mix(a, b, da / (da + db));
    return true;
  }
  return false;
}

void main() {
  g_size = textureSize(u_frame, 0);
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 c;
  if (fetch(p, c)) {
    o_color = vec4(c, 1.0);
    return;
  }
  vec3 h, v;
  bool hh = pair_interp(p, ivec2(1, 0), h), hv = pair_interp(p, ivec2(0, 1), v);
  if (hh && hv) {
    o_color = vec4(0.5 * (h + v), 1.0);
    return;
  }
  if (hh || hv) {
    o_color = vec4(hh ? h : v, 1.0);
    return;
  }
  vec3 d1, d2;
  bool h1 = pair_interp(p, ivec2(1, 1), d1), h2 = pair_interp(p, ivec2(1, -1), d2);
  if (h1 && h2) {
    o_color = vec4(0.5 * (d1 + d2), 1.0);
    return;
  }
  if (h1 || h2) {
    o_color = vec4(h1 ? d1 : d2, 1.0);
    return;
  }
  // Screen edges: the nearest shaded pixel in any of 8 directions.
  float best = 1e9;
  vec3 col = vec3(0.0);
  for (int j = -1; j <= 1; ++j) {
    for (int i = -1; i <= 1; ++i) {
      if (i == 0 && j == 0) continue;
      vec3 q;
      float dq;
      if (probe(p, ivec2(i, j), q, dq) && dq < best) {
        best = dq;
        col = q;
      }
    }
  }
  o_color = vec4(col, 1.0);
}
