// The tiles next to a finer class, in linear light (sRGB targets filter
// decoded values): each pixel reads its tile's class bilinearly at its own
// position and fades into the finer class over one tile, reaching it exactly
// at their common border, so the finer side (the native fovea included) is
// untouched and no tile edge shows. Drawn over those tiles only; every other
// tile is one bilinear read of its class (reconstruct_copy.frag).
// One texel per tile (GL rows): its class (an index into the rates) in bits
// 0-2, the class its neighbours see in bits 3-5 (a tile refined by adapt
// is seen as the coarsest: nothing fades into it), bit 6 set where adapt's
// `smooth` coarsened it.
uniform usampler2D u_classes;
uniform sampler2D u_class0, u_class1, u_class2, u_class3, u_class4, u_class5, u_class6;
uniform vec2 u_extent[7];  // per class: its target's size in screen pixels (texels x rate)
uniform vec2 u_shift[7];   // per class: (rate - 1) / 2, where its samples sit (vrs.cpp)
uniform int u_tile;
out vec4 o_color;

vec3 class_colour(int c, vec2 p) {
  vec2 uv = (p + u_shift[c]) / u_extent[c];
  if (c == 0) return texture(u_class0, uv).rgb;
  if (c == 1) return texture(u_class1, uv).rgb;
  if (c == 2) return texture(u_class2, uv).rgb;
  if (c == 3) return texture(u_class3, uv).rgb;
  if (c == 4) return texture(u_class4, uv).rgb;
  if (c == 5) return texture(u_class5, uv).rgb;
  return texture(u_class6, uv).rgb;
}

void main() {
  vec2 p = gl_FragCoord.xy;
  ivec2 tile = ivec2(p) / u_tile;
  ivec2 grid = textureSize(u_classes, 0);
  int c = int(texelFetch(u_classes, tile, 0).r & 7u);
  vec3 own = class_colour(c, p);
  float nearest = float(u_tile);
  int finer = c;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 n = tile + ivec2(dx, dy);
      if (any(lessThan(n, ivec2(0))) || any(greaterThanEqual(n, grid))) continue;
      int k = int((texelFetch(u_classes, n, 0).r >> 3) & 7u);
      // Finer: a lower index (the rates are ordered by pixels per fragment,
      // 2x4 before 4x2 and 1x2 before 2x1), so every border between classes fades.
      if (k >= c) continue;
      vec2 lo = vec2(n * u_tile), hi = lo + float(u_tile);
      float d = distance(p, clamp(p, lo, hi));
      if (d < nearest) {
        nearest = d;
        finer = k;
      }
    }
  }
  if (finer != c) own = mix(class_colour(finer, p), own, smoothstep(0.0, float(u_tile), nearest));
  o_color = vec4(own, 1.0);
}
