// supersample_edges' packed pass drawn indirectly: instance i covers the
// rectangle edges_list.comp wrote at cover[i] (pixels of a u_viewport-sized
// target), so that the CPU need not know how many entries there are.
#include "pass_kit/edges_rows.glsl"
uniform vec2 u_viewport;
out vec2 v_uv;
void main() {
  ivec4 r = cover[gl_InstanceID];
  // Corners of two triangles: (0,0) (1,0) (0,1) (1,0) (1,1) (0,1).
  const ivec2 corner[6] =
      ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
  ivec2 c = corner[gl_VertexID];
  vec2 px = vec2(c.x == 0 ? r.x : r.z, c.y == 0 ? r.y : r.w);
  v_uv = px / u_viewport;
  gl_Position = vec4(v_uv * 2.0 - 1.0, 0.0, 1.0);
}
