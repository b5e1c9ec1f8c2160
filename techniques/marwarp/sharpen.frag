// The resolve's prefilter, in the buffer (linear light): 1 + 4a at the
// texel, -a at its four neighbours (the angle wraps at u_rows, the rows in
// use: the texture may have more). The inverse mapping
// then reads the result bilinearly, whose response falls below the cutoff
// (0.81 at half of it, 0.41 at it, per axis); with a = 0.12 the two together
// stay within 3 % of flat up to 0.6 of the cutoff and reach 0.6 at it
// (docs/continuous.md). The result is held within its five texels' range:
// no ringing, and no negative light (clamping only at zero would add light
// wherever the content is finer than the texels: 4 % on the detail scene).
// A neighbour not shaded this frame (alpha 0: the buffer is cleared) counts
// as the texel itself.
uniform sampler2D u_buffer;
uniform float u_sharpen;
uniform int u_rows;
out vec4 o_color;
vec3 at(ivec2 q, vec3 own) {
  vec4 v = texelFetch(u_buffer, q, 0);
  return v.a > 0.5 ? v.rgb : own;
}
void main() {
  ivec2 size = textureSize(u_buffer, 0);
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 c = texelFetch(u_buffer, p, 0).rgb;
  vec3 l = at(ivec2(max(p.x - 1, 0), p.y), c);
  vec3 r = at(ivec2(min(p.x + 1, size.x - 1), p.y), c);
  vec3 u = at(ivec2(p.x, (p.y + 1) % u_rows), c);
  vec3 d = at(ivec2(p.x, (p.y + u_rows - 1) % u_rows), c);
  vec3 lo = min(c, min(min(l, r), min(u, d))), hi = max(c, max(max(l, r), max(u, d)));
  vec3 s = (1.0 + 4.0 * u_sharpen) * c - u_sharpen * (l + r + u + d);
  o_color = vec4(clamp(s, lo, hi), 1.0);
}
