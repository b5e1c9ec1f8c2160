// Temporal resolve of one subsampled layer, on its unjittered grid, in linear
// light. While the scene's image and the layer's rectangle hold still
// (u_same_image), a pixel averages its last N jittered samples, one per
// phase: a box filter over the pixel's footprint that converges exactly. A
// sample that differs from the one of the same phase a cycle ago means the
// image changed there, and the pixel restarts. When the image moves, the
// history found at `prev_screen` is clipped to the current samples'
// neighbourhood in YCoCg (mean +- 1.25 sigma of the pixel's sample and its
// four neighbours') and blended exponentially.
// Output: rgb = the resolved colour, a = the pixel's count of same-image
// samples / 255.
uniform sampler2D u_sample;    // this update's samples (jittered; sRGB decoded to linear)
uniform sampler2D u_prev;      // the previous resolve
uniform sampler2DArray u_ring;  // the last N samples, layer = jitter phase
uniform int u_slot_count;      // N
uniform int u_phase;           // this update's phase, 0..N-1
uniform int u_have_history;
uniform int u_same_image;
uniform vec4 u_rect;       // this update's unjittered screen rectangle x0, y0, w, h
uniform vec4 u_prev_rect;  // the previous resolve's
uniform float u_blend;     // the new sample's weight when the image moves
out vec4 o_color;

const float kChangeTolerance = 1.5 / 255.0;  // linear; identical renders differ by 0

vec3 slot(int k) { return texelFetch(u_ring, ivec3(ivec2(gl_FragCoord.xy), k), 0).rgb; }

vec3 to_ycocg(vec3 c) {
  return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b,
              -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}
vec3 from_ycocg(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// The previous resolve at `uv`, Catmull-Rom filtered: a bilinear fetch would
// soften the history a little more at every reprojection, so that under
// motion it drifts towards a blur the eye can see. Five bilinear taps: the
// two middle weights of each axis folded into one, and the four corner taps
// (products of two outer lobes, each at most 0.0055 of the total: a lobe
// peaks at -0.074) left out, the rest renormalised; negative lobes clamped. Alpha (the sample count) comes
// from the middle tap: exact on the unmoved grid, where the weights are
// (0, 1, 0, 0).
vec4 history_catmull_rom(vec2 uv) {
  vec2 size = vec2(textureSize(u_prev, 0));
  vec2 p = uv * size - 0.5;
  vec2 base = floor(p);
  vec2 f = p - base;
  vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
  vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
  vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
  vec2 w3 = f * f * (-0.5 + 0.5 * f);
  vec2 w12 = w1 + w2;
  vec2 t0 = (base - 0.5) / size;
  vec2 t12 = (base + 0.5 + w2 / w12) / size;
  vec2 t3 = (base + 2.5) / size;
  vec4 mid = texture(u_prev, t12);
  float wm = w12.x * w12.y, wl = w0.x * w12.y, wr = w3.x * w12.y, wb = w12.x * w0.y,
        wt = w12.x * w3.y;
  vec3 c = mid.rgb * wm;
  c += texture(u_prev, vec2(t0.x, t12.y)).rgb * wl;
  c += texture(u_prev, vec2(t3.x, t12.y)).rgb * wr;
  c += texture(u_prev, vec2(t12.x, t0.y)).rgb * wb;
  c += texture(u_prev, vec2(t12.x, t3.y)).rgb * wt;
  return vec4(max(c / (wm + wl + wr + wb + wt), vec3(0.0)), mid.a);
}

vec4 foveate_temporal(vec2 prev_screen) {
  ivec2 size = textureSize(u_sample, 0);
  ivec2 ip = ivec2(gl_FragCoord.xy);
  vec3 x = texelFetch(u_sample, ip, 0).rgb;
  if (u_have_history == 0) return vec4(x, 1.0 / 255.0);
  vec2 huv = (prev_screen - u_prev_rect.xy) / u_prev_rect.zw;
  if (any(lessThan(huv, vec2(0.0))) || any(greaterThan(huv, vec2(1.0))))
    return vec4(x, 1.0 / 255.0);
  vec4 prev = history_catmull_rom(huv);
  if (u_same_image != 0) {
    int n = u_slot_count;
    float count = floor(prev.a * 255.0 + 0.5);
    vec3 d = abs(x - slot(u_phase));
    if (count < float(n) || max(d.r, max(d.g, d.b)) <= kChangeTolerance) {
      int c = int(min(count, float(n - 1))) + 1;
      vec3 sum = x;
      for (int k = 1; k < c; ++k) sum += slot((u_phase - k + n) % n);
      return vec4(sum / float(c), float(c) / 255.0);
    }
  }
  vec3 m1 = vec3(0.0), m2 = vec3(0.0);
  const ivec2 kCross[5] = ivec2[5](ivec2(0), ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
  for (int k = 0; k < 5; ++k) {
    vec3 q = to_ycocg(texelFetch(u_sample, clamp(ip + kCross[k], ivec2(0), size - 1), 0).rgb);
    m1 += q;
    m2 += q * q;
  }
  m1 /= 5.0;
  vec3 sigma = sqrt(max(m2 / 5.0 - m1 * m1, vec3(0.0)));
  vec3 h = to_ycocg(prev.rgb);
  vec3 extent = 1.25 * sigma + vec3(1e-4);
  vec3 off = h - m1;
  vec3 a = abs(off / extent);
  float worst = max(a.x, max(a.y, a.z));
  if (worst > 1.0) h = m1 + off / worst;
  return vec4(max(from_ycocg(mix(h, to_ycocg(x), u_blend)), vec3(0.0)), 1.0 / 255.0);
}
