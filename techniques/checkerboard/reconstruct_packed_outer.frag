// Reconstruction with packed quads (block 1), beyond region 2: every pixel
// is in region 3, where quad 0 alone is kept, and is quad 0's lattice read
// bilinearly at its position (packed.glsl): one read per pixel.
#include "checkerboard/packed.glsl"
layout(early_fragment_tests) in;
out vec4 o_color;
void main() { o_color = vec4(mean_of(read_quad(u_quad0, gl_FragCoord.xy, u_offset0)), 1.0); }
