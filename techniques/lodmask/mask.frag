// A circular mask for the next, finer LOD. Inside the circle the stencil gets
// the pass's reference value, depth is reset to the far plane and every
// G-buffer attachment is cleared to zero, the scene's "no surface"
// (Scene::prepass_begin clears to zero). The finer LOD drawn next then
// replaces the coarser one there, and where it has no surface the background
// shows, as in native, instead of a stale coarser surface.
uniform vec2 u_centre;
uniform float u_radius;
// Outputs with no draw buffer behind them are dropped: eight cover any G-buffer.
layout(location = 0) out vec4 o_gbuffer[8];
void main() {
  if (distance(gl_FragCoord.xy, u_centre) > u_radius) discard;
  gl_FragDepth = 1.0;
  for (int i = 0; i < 8; ++i) o_gbuffer[i] = vec4(0.0);
}
