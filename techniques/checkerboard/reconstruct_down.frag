// Reconstruction, pass 1 (see filter.glsl): the frame (linear colour times
// coverage, coverage) averaged over 2x2 blocks, one bilinear read at each
// block's centre. Blocks that no later pass reads (inside the native fovea)
// are skipped.
#include "checkerboard/filter.glsl"
uniform sampler2D u_frame;
uniform float u_skip_radius;  // full-resolution pixels nearer the gaze than this are not read
out vec4 o_color;
void main() {
  vec2 full = 2.0 * gl_FragCoord.xy;  // the block's centre at full resolution
  if (distance(pattern_top_left(full), u_gaze_top_left) < u_skip_radius) {
    o_color = vec4(0.0);
    return;
  }
  o_color = texture(u_frame, full / vec2(textureSize(u_frame, 0)));
}
