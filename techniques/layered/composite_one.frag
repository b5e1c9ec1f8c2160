// The composite where one layer alone shows: inside the inner layer's radius
// e_1 (its blend weight is 1) and beyond every blend band (only the outer
// layer). One read of that layer through a sampler of its own: composite.frag
// reads every layer through an array indexed in a loop, which llvmpipe pays
// for on every pixel (2.4 times this pass's time beyond the bands, which
// cover most of the screen).
uniform sampler2D u_layer;
uniform vec4 u_layer_rect;  // x0, y0, w, h in screen pixels
layout(early_fragment_tests) in;
out vec4 o_color;
void main() {
  vec2 uv = (gl_FragCoord.xy - u_layer_rect.xy) / u_layer_rect.zw;
  o_color = vec4(texture(u_layer, uv).rgb, 1.0);
}
