// The hardware path's coarse tiles, in linear light (the sRGB frame decodes
// on read). The driver shaded one invocation per coarse fragment (rw x rh
// pixels, aligned to the rate's grid, at the fragment's centre) and wrote its
// colour to every pixel of the fragment: left alone, that is a mosaic of
// blocks. Each pixel instead reads the four fragment centres around it and
// interpolates them bilinearly, as the emulation's bilinear read of a
// reduced-resolution class does. A centre that falls in a tile of another
// rate reads whatever that tile shaded there.
//
// Where a tile borders a finer one, the driver shaded it at the finest rate
// around it (u_shade; its own, the model's, is u_own), so that it can fade
// into its finer neighbour over one tile as the emulation does: from that
// neighbour's rate at their common border to its own rate one tile away,
// where its own rate is made from the shaded pixels by averaging each of its
// own fragments' blocks (a box prefilter) and interpolating between their
// centres. Drawn over every tile but the 1x1 ones.
uniform sampler2D u_frame;     // the frame as the driver shaded it (bilinear, clamped)
uniform usampler2D u_shade;    // per tile: the rate it was shaded at (index into the rates, GL rows)
uniform usampler2D u_own;      // per tile: the model's rate for it
uniform vec2 u_rates[7];       // per class: the fragment's width and height in pixels
uniform int u_tile;
// Where a coarse fragment's colour was computed, past its centre along each
// axis it spans: 0 where the scene shades the point it is given (procedural
// scenes), 0.5 where it reads the G-buffer pixel there (texel at the centre,
// whose own centre is half a pixel on).
uniform float u_sample_offset;
out vec4 o_color;

vec2 g_size;

// One bilinear read at `p` (pixels): at a corner between pixels, their mean.
vec3 at(vec2 p) { return texture(u_frame, clamp(p, vec2(0.5), g_size - 0.5) / g_size).rgb; }

// The colour of block `b` of a rate-sized grid: at its sample point (`mean`
// false: in a fragment of this rate its one colour, in a finer-shaded tile
// the pixels around that point averaged), or the mean of its pixels, two by
// two.
vec3 block(ivec2 b, ivec2 rate, bool mean) {
  vec2 origin = vec2(b * rate);
  if (!mean) {
    vec2 offset = vec2(greaterThan(rate, ivec2(1))) * u_sample_offset;
    return at(origin + 0.5 * vec2(rate) + offset);
  }
  ivec2 n = max(rate / 2, ivec2(1));
  vec2 first = mix(vec2(1.0), vec2(0.5), vec2(equal(rate, ivec2(1))));
  vec3 sum = vec3(0.0);
  for (int y = 0; y < n.y; ++y)
    for (int x = 0; x < n.x; ++x) sum += at(origin + first + 2.0 * vec2(x, y));
  return sum / float(n.x * n.y);
}

// Bilinear between the sample points of the grid's blocks around `p`.
vec3 interpolate(vec2 p, ivec2 rate, bool mean) {
  vec2 offset = mean ? vec2(0.0) : vec2(greaterThan(rate, ivec2(1))) * u_sample_offset;
  vec2 q = (p - offset) / vec2(rate) - 0.5;
  vec2 f = floor(q), t = q - f;
  ivec2 b = ivec2(f);
  vec3 low = mix(block(b, rate, mean), block(b + ivec2(1, 0), rate, mean), t.x);
  vec3 high = mix(block(b + ivec2(0, 1), rate, mean), block(b + ivec2(1, 1), rate, mean), t.x);
  return mix(low, high, t.y);
}

void main() {
  g_size = vec2(textureSize(u_frame, 0));
  vec2 p = gl_FragCoord.xy;
  ivec2 tile = ivec2(p) / u_tile;
  ivec2 shade = ivec2(u_rates[texelFetch(u_shade, tile, 0).r]);
  ivec2 own = ivec2(u_rates[texelFetch(u_own, tile, 0).r]);
  vec3 colour = interpolate(p, shade, false);
  if (shade != own) {
    // The nearest neighbour finer than this tile's own rate in either axis.
    ivec2 grid = textureSize(u_own, 0);
    float nearest = float(u_tile);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        ivec2 n = tile + ivec2(dx, dy);
        if (any(lessThan(n, ivec2(0))) || any(greaterThanEqual(n, grid))) continue;
        ivec2 r = ivec2(u_rates[texelFetch(u_own, n, 0).r]);
        if (!any(lessThan(r, own))) continue;
        vec2 lo = vec2(n * u_tile), hi = lo + float(u_tile);
        nearest = min(nearest, distance(p, clamp(p, lo, hi)));
      }
    }
    colour = mix(colour, interpolate(p, own, true), smoothstep(0.0, float(u_tile), nearest));
  }
  o_color = vec4(colour, 1.0);
}
