// The composite where one layer alone shows: inside the inner layer's radius
// e_1 (its blend weight is 1) and beyond every blend band (only the outer
// layer, over most of the screen). One read of that layer through a sampler
// of its own: composite.frag reads the layers through an array indexed in a
// loop, which llvmpipe pays for on every pixel (docs/performance.md).
uniform sampler2D u_layer;
uniform vec4 u_layer_rect;  // x0, y0, w, h in screen pixels
layout(early_fragment_tests) in;
out vec4 o_color;
void main() {
  vec2 uv = (gl_FragCoord.xy - u_layer_rect.xy) / u_layer_rect.zw;
  o_color = vec4(texture(u_layer, uv).rgb, 1.0);
}
