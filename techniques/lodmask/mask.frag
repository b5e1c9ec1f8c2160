// A circular stencil mask that also resets depth to the far plane inside.
uniform vec2 u_centre;
uniform float u_radius;
void main() {
  if (distance(gl_FragCoord.xy, u_centre) > u_radius) discard;
  gl_FragDepth = 1.0;
}
