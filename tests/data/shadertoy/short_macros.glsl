// Short macro names, as golfed shaders use them: they end with this file and
// rewrite nothing foveate appends after it (its adapter, a technique's main,
// the colour helpers). Renders orange: (1, 0.5, 0).
#define c vec2(1., .5)
#define o_color o
#define col colour
#define p vec3(0)
#define uv v
void mainImage(out vec4 o, vec2 u) { o = vec4(c, p.x, 1.); }
