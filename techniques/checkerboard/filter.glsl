// Reconstruction of the checkerboard as a normalized convolution over the
// kept samples, in linear light: the frame holds linear colour times
// coverage (dropped quads are cleared to zero) and coverage in alpha, so a
// Gaussian of the frame divided by its alpha is the Gaussian-weighted mean of
// the kept samples around each pixel. Its width follows each region's largest
// gap between kept samples (u_sigmas = filter fraction * checkerboard_gap_px),
// wide enough that the kept quads leave no pattern: at the pattern's
// fundamental frequency, 1 / (2n), the Gaussian passes a few per cent.
// At a reduced scale f (2 or 4 pixels per texel), since the blur is wider
// than that anyway: the frame is averaged in f x f blocks (coverage too),
// filtered by a separable Gaussian (a horizontal, then a vertical pass, each
// reading its input bilinearly between pairs of texels: one fetch for two
// taps) and read back bilinearly; the Gaussian's width is what remains of
// sigma after the block average and the bilinear read-back (variances
// (f^2 - 1) / 12 and f^2 / 6 pixel^2 per axis: 1/4 and 2/3 at f = 2).
// The width grows smoothly with the distance d from the gaze: it reaches
// each region's width at the region's threshold, ramping up over the blend
// band before it, so that the blur has no step where the tiles' regions
// change (a pixel never gets less than its own region's width).
#include "checkerboard/pattern.glsl"
uniform vec3 u_sigmas;  // Gaussian sigma of regions 1..3, pixels
uniform vec2 u_blend;   // radius of the native fovea, width of the blend band (pixels)
uniform float u_scale;  // f: full-resolution pixels per texel of the filtered image

// The width at a full-resolution position.
float filter_sigma(vec2 frag_gl) {
  float d = distance(pattern_top_left(frag_gl), u_gaze_top_left);
  float ramp = max(u_blend.y, 1.0);
  float s = u_sigmas.x;
  s = mix(s, u_sigmas.y, smoothstep(u_thresholds.y - ramp, u_thresholds.y, d));
  return mix(s, u_sigmas.z, smoothstep(u_thresholds.z - ramp, u_thresholds.z, d));
}

// Weighted sum along `axis` (premultiplied RGBA) of `tex` around pixel `ip`.
vec4 filter_axis(sampler2D tex, ivec2 ip, vec2 axis, float sigma) {
  vec2 size = vec2(textureSize(tex, 0));
  vec2 centre = vec2(ip) + 0.5;
  int r = int(ceil(3.0 * sigma));
  float k = -0.5 / (sigma * sigma);
  vec4 acc = texelFetch(tex, ip, 0);
  for (int i = 1; i <= r; i += 2) {
    float wa = exp(k * float(i * i)), wb = i + 1 <= r ? exp(k * float((i + 1) * (i + 1))) : 0.0;
    float w = wa + wb;
    float o = float(i) + wb / w;
    acc += w * (texture(tex, (centre + o * axis) / size) + texture(tex, (centre - o * axis) / size));
  }
  return acc;
}

// The width of the reduced-scale Gaussian (in its texels) that gives sigma
// at full resolution with the block average and the read-back.
float scaled_sigma(float sigma) {
  float f = u_scale;
  float rest = sigma * sigma - (f * f - 1.0) / 12.0 - f * f / 6.0;
  return max(sqrt(max(rest, 0.0)) / f, 0.25);
}
