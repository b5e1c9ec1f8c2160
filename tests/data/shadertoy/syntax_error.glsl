// Line 2 is fine; line 4 has an error.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 col = vec3(1.0);
  col = col * ;
  fragColor = vec4(col, 1.0);
}
