// Reconstruction, pass 1 (see filter.glsl): the frame (linear colour times
// coverage, coverage) averaged over f x f blocks. Along each axis the block's
// pixels are read in pairs (one bilinear read between two pixel centres),
// the last one alone when f is odd. Blocks that no later pass reads (inside
// the native fovea) are skipped.
#include "checkerboard/filter.glsl"
uniform sampler2D u_frame;
uniform float u_skip_radius;  // full-resolution pixels nearer the gaze than this are not read
out vec4 o_color;

// Position (pixels from the block's first edge) and weight of read k along an axis.
vec2 block_read(int k, int f) {
  return 2 * k + 1 < f ? vec2(float(2 * k + 1), 2.0) : vec2(float(f) - 0.5, 1.0);
}

void main() {
  vec2 full = u_scale * gl_FragCoord.xy;  // the block's centre at full resolution
  if (distance(pattern_top_left(full), u_gaze_top_left) < u_skip_radius) {
    o_color = vec4(0.0);
    return;
  }
  int f = int(u_scale);
  int reads = (f + 1) / 2;
  vec2 origin = floor(gl_FragCoord.xy) * u_scale;  // the block's lower-left edge
  vec2 size = vec2(textureSize(u_frame, 0));
  vec4 acc = vec4(0.0);
  for (int j = 0; j < reads; ++j) {
    vec2 y = block_read(j, f);
    for (int i = 0; i < reads; ++i) {
      vec2 x = block_read(i, f);
      acc += x.y * y.y * texture(u_frame, (origin + vec2(x.x, y.x)) / size);
    }
  }
  o_color = acc / (u_scale * u_scale);
}
