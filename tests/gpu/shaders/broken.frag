// A fragment shader with an error on line 5, after an include.
#include "lib/colour.glsl"
out vec4 o_color;
void main() {
  o_color = test_colour() + undefined_thing;
}
