// Includes a snippet and writes its colour.
#include "lib/colour.glsl"
out vec4 o_color;
void main() { o_color = test_colour(); }
