// The resolve beyond the native disc's blend band: the buffer alone.
#include "marwarp/resolve_common.glsl"
layout(early_fragment_tests) in;
out vec4 o_color;
void main() { o_color = vec4(buffer_colour(), 1.0); }
