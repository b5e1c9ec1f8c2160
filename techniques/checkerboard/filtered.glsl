// The reconstruction at a full-resolution pixel: the filtered sums read back
// bilinearly and divided by their coverage (see filter.glsl).
uniform sampler2D u_filtered;
uniform float u_scale;

vec4 filtered_sums(vec2 frag_gl) {
  return texture(u_filtered, frag_gl / (u_scale * vec2(textureSize(u_filtered, 0))));
}
