// Box-filters an N x N supersampled image down to the target, in linear light
// (the source is sRGB-encoded and decodes on fetch; the target encodes).
uniform sampler2D u_source;
uniform int u_factor;
out vec4 o_color;
void main() {
  ivec2 base = ivec2(gl_FragCoord.xy) * u_factor;
  vec3 sum = vec3(0.0);
  for (int j = 0; j < u_factor; ++j) {
    for (int i = 0; i < u_factor; ++i) sum += texelFetch(u_source, base + ivec2(i, j), 0).rgb;
  }
  o_color = vec4(sum / float(u_factor * u_factor), 1.0);
}
