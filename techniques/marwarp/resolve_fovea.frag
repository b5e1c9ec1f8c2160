// The resolve inside the native disc: native pixels.
#include "marwarp/resolve_common.glsl"
layout(early_fragment_tests) in;
out vec4 o_color;
void main() { o_color = vec4(native_pixel(), 1.0); }
