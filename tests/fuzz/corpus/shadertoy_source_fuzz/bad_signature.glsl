void mainImage(out vec3 c, vec2 p) { c = vec3(p, 0.); }
void


helper(){}
