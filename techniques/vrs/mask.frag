// The stencil mask of one rate class in its reduced-resolution target. The
// reconstruction reads a class in its own tiles and in the coarser tiles next
// to them (which fade into it over one tile), each read bilinear: a texel is
// kept when the pixels that may read it (its footprint and one texel either
// side) touch such a tile. Classes are ordered finest first (1x1, 1x2, 2x1,
// 2x2, 2x4, 4x2, 4x4), so a higher index is coarser.
uniform usampler2D u_classes;  // one texel per tile: index into the rates (GL rows)
uniform int u_class;
uniform vec2 u_rate;  // pixels per fragment of this class (whole numbers)
uniform int u_tile;
out vec4 o_color;

int class_at(ivec2 t) { return int(texelFetch(u_classes, t, 0).r); }

bool coarser_neighbour(ivec2 t, ivec2 grid) {
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 n = t + ivec2(dx, dy);
      if (all(greaterThanEqual(n, ivec2(0))) && all(lessThan(n, grid)) && class_at(n) == u_class)
        return true;
    }
  }
  return false;
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy), rate = ivec2(u_rate);
  ivec2 grid = textureSize(u_classes, 0);
  ivec2 lo = max((texel - 1) * rate, ivec2(0)) / u_tile;
  ivec2 hi = min(((texel + 2) * rate - 1) / u_tile, grid - 1);
  for (int ty = lo.y; ty <= hi.y; ++ty) {
    for (int tx = lo.x; tx <= hi.x; ++tx) {
      int k = class_at(ivec2(tx, ty));
      if (k == u_class || (k > u_class && coarser_neighbour(ivec2(tx, ty), grid))) {
        o_color = vec4(0.0);
        return;
      }
    }
  }
  discard;
}
