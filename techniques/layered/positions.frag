// The world point seen at each pixel of a layer's unjittered grid (from the
// scene's G-buffer), kept with the layer so that it can be reprojected on the
// frames it is not updated (half rate).
uniform sampler2D u_sample;  // the layer (for its size)
uniform vec4 u_rect;         // unjittered screen rectangle x0, y0, w, h
out vec4 o_color;
void main() {
  vec2 size = vec2(textureSize(u_sample, 0));
  o_color = vec4(scene_world_position(u_rect.xy + gl_FragCoord.xy * (u_rect.zw / size)), 1.0);
}
