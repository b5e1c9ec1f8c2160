// Inspection overlay: outlines of circles and rectangles and gaze dots.
uniform int u_count;
uniform vec4 u_shape[32];   // x, y, w, h in GL pixels (rect: corner + size; circle/dot: centre + radius)
uniform vec4 u_style[32];   // r, g, b, kind (0 circle, 1 rect, 2 dot)
out vec4 o_color;
void main() {
  vec2 p = gl_FragCoord.xy;
  vec4 acc = vec4(0.0);
  for (int i = 0; i < u_count; ++i) {
    vec4 s = u_shape[i];
    vec4 st = u_style[i];
    float a = 0.0;
    if (st.w < 0.5) {
      a = 1.0 - smoothstep(1.0, 2.0, abs(distance(p, s.xy) - s.z));
    } else if (st.w < 1.5) {
      vec2 d = abs(p - (s.xy + 0.5 * s.zw)) - 0.5 * s.zw;
      float edge = abs(max(d.x, d.y));
      a = (max(d.x, d.y) < 2.0) ? 1.0 - smoothstep(1.0, 2.0, edge) : 0.0;
    } else {
      a = 1.0 - smoothstep(s.z - 1.0, s.z, distance(p, s.xy));
    }
    acc = max(acc, vec4(st.rgb * a, a));
  }
  if (acc.a <= 0.0) discard;
  o_color = vec4(acc.rgb / acc.a, acc.a);
}
