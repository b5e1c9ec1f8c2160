// The composite inside the inner layer's radius e_1, where the blend weight
// of the native-rate inner layer is 1 and nothing else shows: one read of
// that layer (composite.frag would read every layer there, and llvmpipe pays
// for each fetch). Drawn over a polygon inscribed in the disc.
uniform sampler2D u_inner;
uniform vec4 u_inner_rect;  // x0, y0, w, h in screen pixels
layout(early_fragment_tests) in;
out vec4 o_color;
void main() {
  vec2 uv = (gl_FragCoord.xy - u_inner_rect.xy) / u_inner_rect.zw;
  o_color = vec4(texture(u_inner, uv).rgb, 1.0);
}
