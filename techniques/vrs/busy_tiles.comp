// vrs adapt: ContentAdapt::measure on the GPU, one invocation per tile of
// class u_class; bit 0 of a tile's byte says busy, bit 1 smooth. Other tiles
// are left as they are.
// Busy: at least u_share of its sample pairs differ: samples 4 pixels apart
// whatever the class (u_step texels), each paired with the next to its right
// and above; a pair differs when the linear luminances differ by more than
// u_contrast of the brighter; a texel left unshaded (alpha 0) forms no pair.
// Smooth (u_smooth above 0): its first texel shaded, and at every texel of
// the tile shaded with both neighbours along an axis shaded, no colour
// channel leaves the mean of those two neighbours by more than u_smooth of
// the texel's luminance (at least kDark): bilinear interpolation at twice
// the spacing would have made the texels the coarser rate drops within that
// share. A tile already shaded a step coarser than the model asks (bit 6 of
// its class byte) is judged against 4 u_smooth: on content of constant
// curvature the second difference at twice the spacing is four times that
// at the spacing, so a tile coarsened stays so while the content that
// coarsened it holds.
layout(local_size_x = 8, local_size_y = 8) in;
layout(r8ui, binding = 0) uniform writeonly uimage2D u_busy;
uniform usampler2D u_classes;  // the frame's class per tile (bits 0-2), coarsened (bit 6)
uniform sampler2D u_target;    // class u_class's target (sRGB: fetched linear)
uniform int u_class;
uniform ivec2 u_rate;   // the class's rate in pixels
uniform ivec2 u_step;   // 4 pixels in texels
uniform int u_tile;     // pixels
uniform ivec2 u_frame;  // pixels
uniform float u_contrast;
uniform float u_share;   // 0: busyness not judged
uniform float u_smooth;  // 0: smoothness not judged

// Linear luminance under which the smoothness threshold stops shrinking:
// about the display's black level with its reflections (0.5 % of peak).
const float kDark = 0.005;

float luminance(vec4 c) { return dot(c.rgb, vec3(0.2126, 0.7152, 0.0722)); }

// 1 when the pair differs, 0 when not, -1 when either is unshaded.
int differs(vec4 a, vec4 b) {
  if (a.a < 1.0 || b.a < 1.0) return -1;
  float la = luminance(a), lb = luminance(b);
  return abs(la - lb) > u_contrast * max(la, lb) ? 1 : 0;
}

vec4 at(ivec2 p, ivec2 size) {
  if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) return vec4(0.0);
  return texelFetch(u_target, p, 0);
}

// How far texel `c` leaves the mean of `a` and `b` (either side along an
// axis), in its luminance; 0 where it or either neighbour is unshaded.
float curvature(vec4 a, vec4 c, vec4 b) {
  if (a.a < 1.0 || b.a < 1.0 || c.a < 1.0) return 0.0;
  vec3 d = abs(c.rgb - 0.5 * (a.rgb + b.rgb));
  return max(d.r, max(d.g, d.b)) / max(luminance(c), kDark);
}

// The largest curvature along the line of texels from `p` in steps of `d`,
// `n` texels, each fetched once (a window of three slides along it).
float line_curvature(ivec2 p, ivec2 d, int n, ivec2 size) {
  vec4 a = at(p - d, size), c = at(p, size);
  float most = 0.0;
  for (int k = 0; k < n; ++k) {
    vec4 b = at(p + (k + 1) * d, size);
    most = max(most, curvature(a, c, b));
    a = c;
    c = b;
  }
  return most;
}

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, textureSize(u_classes, 0)))) return;
  uint byte = texelFetch(u_classes, t, 0).r;
  if (int(byte & 7u) != u_class) return;
  ivec2 size = textureSize(u_target, 0);
  ivec2 lo = t * u_tile / u_rate;
  ivec2 hi = (min((t + 1) * u_tile, u_frame) - 1) / u_rate;
  int pairs = 0, differing = 0;
  for (int j = lo.y; u_share > 0.0 && j <= hi.y && j < size.y; j += u_step.y) {
    for (int i = lo.x; i <= hi.x && i < size.x; i += u_step.x) {
      vec4 a = texelFetch(u_target, ivec2(i, j), 0);
      if (i + u_step.x < size.x) {
        int d = differs(a, texelFetch(u_target, ivec2(i + u_step.x, j), 0));
        if (d >= 0) { ++pairs; differing += d; }
      }
      if (j + u_step.y < size.y) {
        int d = differs(a, texelFetch(u_target, ivec2(i, j + u_step.y), 0));
        if (d >= 0) { ++pairs; differing += d; }
      }
    }
  }
  bool busy = pairs > 0 && float(differing) >= u_share * float(pairs);
  bool flat_enough = false;
  // Judged where it can coarsen a tile: at 1x1 or 2x2 and not refined by
  // adapt (which its neighbours see as another class), or coarsened.
  bool coarsened = (byte & 64u) != 0u;
  bool refined = ((byte >> 3) & 7u) != (byte & 7u);
  if (u_smooth > 0.0 && (coarsened || (!refined && (u_rate == ivec2(1) || u_rate == ivec2(2))))) {
    float bound = (coarsened ? 4.0 : 1.0) * u_smooth;
    ivec2 top = min(hi, size - 1);
    float most = 0.0;
    for (int j = lo.y; j <= top.y; ++j)
      most = max(most, line_curvature(ivec2(lo.x, j), ivec2(1, 0), top.x - lo.x + 1, size));
    for (int i = lo.x; i <= top.x; ++i)
      most = max(most, line_curvature(ivec2(i, lo.y), ivec2(0, 1), top.y - lo.y + 1, size));
    // A tile with nothing shaded in it says nothing.
    bool judged = texelFetch(u_target, lo, 0).a >= 1.0;
    flat_enough = judged && most <= bound;
  }
  imageStore(u_busy, t, uvec4((busy ? 1u : 0u) | (flat_enough ? 2u : 0u)));
}
