// Fills the G-buffer, packed into one RGBA32UI attachment (deferred_common.glsl
// unpacks it):
//   x  the distance from the eye to the surface at the fragment (fp32 bits):
//      the position is the eye plus the ray through the texel's centre times
//      it, exact but for rounding, in 4 bytes instead of 12;
//   y  albedo rgb and material id (unorm8 x4, as an RGBA8 target stores them);
//   z  the octahedral normal (snorm16 x2);
//   w  gloss and coverage (half x2; coverage 1 where a surface was drawn, the
//      clear leaves 0).
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
layout(location = 0) out uvec4 o_surface;

#include "octahedral.glsl"
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
  o_surface = uvec4(floatBitsToUint(distance(v_world, u_eye)),
                    packUnorm4x8(vec4(c, u_material / 255.0)), packSnorm2x16(octahedral_encode(n)),
                    packHalf2x16(vec2(u_gloss, 1.0)));
}
