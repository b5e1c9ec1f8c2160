// One quad per rectangle (see foveate/techniques/rect_pass.hpp): instance i covers
// u_rects[i] = (x0, y0, x1, y1), GL pixels of a u_viewport-sized target.
layout(std430, binding = 0) readonly buffer Rects { ivec4 u_rects[]; };
uniform vec2 u_viewport;
void main() {
  ivec4 r = u_rects[gl_InstanceID];
  // Corners of two triangles: (0,0) (1,0) (0,1) (1,0) (1,1) (0,1).
  const ivec2 corner[6] =
      ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
  ivec2 c = corner[gl_VertexID];
  vec2 px = vec2(c.x == 0 ? r.x : r.z, c.y == 0 ? r.y : r.w);
  gl_Position = vec4(px / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
