// Line 3 uses a name nobody declared: the error names this file, line 3.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  fragColor = vec4(undeclared_thing, 1.0);
}
