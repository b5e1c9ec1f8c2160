// vrs adapt: ContentAdapt::measure on the GPU, one invocation per tile. A
// tile of class u_class is busy when at least u_share of its sample pairs
// differ: samples 4 pixels apart whatever the class (u_step texels), each
// paired with the next to its right and above; a pair differs when the
// linear luminances differ by more than u_contrast of the brighter; a texel
// left unshaded (alpha 0) forms no pair. Other tiles are left as they are.
layout(local_size_x = 8, local_size_y = 8) in;
layout(r8ui, binding = 0) uniform writeonly uimage2D u_busy;
uniform usampler2D u_classes;  // the frame's class per tile (bits 0-2)
uniform sampler2D u_target;    // class u_class's target (sRGB: fetched linear)
uniform int u_class;
uniform ivec2 u_rate;   // the class's rate in pixels
uniform ivec2 u_step;   // 4 pixels in texels
uniform int u_tile;     // pixels
uniform ivec2 u_frame;  // pixels
uniform float u_contrast;
uniform float u_share;

float luminance(vec4 c) { return dot(c.rgb, vec3(0.2126, 0.7152, 0.0722)); }

// 1 when the pair differs, 0 when not, -1 when either is unshaded.
int differs(vec4 a, vec4 b) {
  if (a.a < 1.0 || b.a < 1.0) return -1;
  float la = luminance(a), lb = luminance(b);
  return abs(la - lb) > u_contrast * max(la, lb) ? 1 : 0;
}

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, textureSize(u_classes, 0)))) return;
  if (int(texelFetch(u_classes, t, 0).r & 7u) != u_class) return;
  ivec2 size = textureSize(u_target, 0);
  ivec2 lo = t * u_tile / u_rate;
  ivec2 hi = (min((t + 1) * u_tile, u_frame) - 1) / u_rate;
  int pairs = 0, differing = 0;
  for (int j = lo.y; j <= hi.y && j < size.y; j += u_step.y) {
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
  imageStore(u_busy, t, uvec4(busy ? 1u : 0u));
}
