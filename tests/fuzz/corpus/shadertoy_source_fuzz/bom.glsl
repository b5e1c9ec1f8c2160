// Starts with a UTF-8 byte order mark (as some editors save): skipped.
void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(0.0, 1.0, 0.0, 1.0); }
