// The stencil mask of one rate class in its reduced-resolution target: a
// texel is kept when the screen footprint it and its bilinear neighbours
// cover, grown by one tile (the reconstruction blends a coarser tile towards
// a finer neighbour over one tile), touches a tile of the class.
uniform usampler2D u_classes;  // one texel per tile: index into the rates (GL rows)
uniform int u_class;
uniform vec2 u_rate;  // pixels per fragment of this class (whole numbers)
uniform int u_tile;
out vec4 o_color;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy), rate = ivec2(u_rate);
  ivec2 grid = textureSize(u_classes, 0);
  ivec2 lo = max((texel - 1) * rate - u_tile, ivec2(0)) / u_tile;
  ivec2 hi = min(((texel + 2) * rate + u_tile - 1) / u_tile, grid - 1);
  for (int ty = lo.y; ty <= hi.y; ++ty) {
    for (int tx = lo.x; tx <= hi.x; ++tx) {
      if (int(texelFetch(u_classes, ivec2(tx, ty), 0).r) == u_class) {
        o_color = vec4(0.0);
        return;
      }
    }
  }
  discard;
}
