// mainImage with the wrong parameters.
void mainImage(out vec3 fragColor, in vec2 fragCoord) { fragColor = vec3(1.0); }
