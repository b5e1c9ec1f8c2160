// Fills the G-buffer: albedo and material id, normal and gloss, world position.
// Compiled twice: with FOVEATE_ALBEDO_TEXTURE for textured materials, without
// for the rest. A texture read under a uniform branch still costs llvmpipe
// its fetch on every fragment (a third of a 1080p G-buffer pass on `guenter`,
// whose materials have no texture); the two programs write the same values.
in vec3 v_world;
in vec3 v_normal;
uniform vec4 u_base_color;
#ifdef FOVEATE_ALBEDO_TEXTURE
in vec2 v_uv;
uniform sampler2D u_albedo_tex;
#endif
uniform float u_material;
uniform float u_gloss;
uniform vec3 u_eye;  // world position of the eye
layout(location = 0) out vec4 o_albedo;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_position;
void main() {
  vec3 c = u_base_color.rgb;
#ifdef FOVEATE_ALBEDO_TEXTURE
  c *= pow(texture(u_albedo_tex, v_uv).rgb, vec3(2.2));  // sRGB texels to linear
#endif
  // The normal of the side the eye sees, whatever the triangle's winding
  // (files disagree on it, and by gl_FrontFacing's word a clockwise mesh's
  // normals would point inward: lit from behind). The face's own normal
  // comes from the screen-space derivatives of its world position, turned
  // towards the eye; a degenerate face (a zero cross product) keeps the
  // mesh's normal.
  vec3 n = normalize(v_normal);
  vec3 face = cross(dFdx(v_world), dFdy(v_world));
  if (dot(face, u_eye - v_world) < 0.0) face = -face;
  if (dot(n, face) < 0.0) n = -n;
  o_albedo = vec4(c, u_material / 255.0);
  o_normal = vec4(n, u_gloss);
  o_position = vec4(v_world, 1.0);
}
