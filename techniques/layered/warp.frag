// A layer shown stale (half rate) moved with the camera, at the layer's own
// resolution: each texel is read where its world point was when the layer was
// rendered (reverse reprojection, one fixed-point step). The composite then
// reads the warped layer like a fresh one, one fetch per pixel.
in vec2 v_uv;
uniform sampler2D u_layer;
uniform sampler2D u_positions;  // world point of each texel of the layer's render
uniform vec4 u_rect;            // the layer's x0, y0, w, h in screen pixels
uniform mat4 u_layer_view_proj;  // the camera it was rendered with
uniform mat4 u_view_proj;        // this frame's camera
uniform vec2 u_frame_size;
out vec4 o_color;
void main() {
  vec2 uv = v_uv;
  vec4 x = vec4(texture(u_positions, uv).xyz, 1.0);
  vec4 now = u_view_proj * x, then = u_layer_view_proj * x;
  if (now.w > 0.0 && then.w > 0.0) {
    vec2 p = u_rect.xy + uv * u_rect.zw;
    vec2 q = p - (now.xy / now.w - then.xy / then.w) * 0.5 * u_frame_size;
    uv = (q - u_rect.xy) / u_rect.zw;
  }
  o_color = texture(u_layer, uv);
}
