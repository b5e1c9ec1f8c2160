// Reconstruction with packed quads (block 1; checkerboard.cpp) over regions
// 0-2 and their borders, in linear light: region 0 is the frame; beyond it
// each quad's target is read at the pixel's own position (packed.glsl). At a
// kept pixel that read is its own sample. At a dropped pixel of regions 1 and
// 2 (quad 1 or 2 of its tile), quad 0's read is the mean of its two
// neighbours along one axis and quad 3's of its two along the other, so their
// sum weighs its four neighbours alike. In region 3, where quad 0 alone is
// kept, quad 0's read interpolates its lattice (reconstruct_packed_outer.frag
// beyond region 2).
#include "checkerboard/pattern.glsl"
#include "checkerboard/packed.glsl"
uniform sampler2D u_frame;
uniform sampler2D u_quad2, u_quad3;
uniform vec2 u_offset3;  // quad 3's pixel in each 2x2 block of GL pixels
layout(early_fragment_tests) in;
out vec4 o_color;

void main() {
  ivec2 ip = ivec2(gl_FragCoord.xy);
  vec2 c = vec2(ip) + 0.5;
  int region = pattern_region(c);
  if (region == 0) {
    o_color = vec4(texelFetch(u_frame, ip, 0).rgb, 1.0);
    return;
  }
  vec2 m = mod(pattern_top_left(c), 2.0);
  int quad = (m.x >= 1.0 ? 2 : 0) + (m.y >= 1.0 ? 1 : 0);
  vec4 a = read_quad(u_quad0, c, u_offset0);
  if (region == 3 || quad == 0) {
    o_color = vec4(mean_of(a), 1.0);
    return;
  }
  if (region == 1 && quad == 2) {
    o_color = vec4(texelFetch(u_quad2, ip / 2, 0).rgb, 1.0);
    return;
  }
  vec4 b = read_quad(u_quad3, c, u_offset3);
  o_color = vec4(quad == 3 ? mean_of(b) : mean_of(a + b), 1.0);
}
