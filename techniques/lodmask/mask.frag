// A circular stencil mask: fragments outside the circle are discarded; the
// pass's stencil state marks the ones inside.
uniform vec2 u_centre;
uniform float u_radius;
void main() {
  if (distance(gl_FragCoord.xy, u_centre) > u_radius) discard;
}
