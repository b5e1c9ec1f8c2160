// A shading pass: the technique's mapping gives the screen position, the
// scene shades it. No discard here, and no keep rectangle: on llvmpipe a
// shader that can discard ran raymarch 45 % slower even where it never did
// (native's frame 1.45 s against 1.0 s at 1080p). What a pass must not shade
// it leaves out with the cover it draws over (Kit::shade).
#include "color.glsl"
out vec4 o_color;
void main() { o_color = vec4(foveate_linear(scene_shade(foveate_map(gl_FragCoord.xy)).rgb), 1.0); }
