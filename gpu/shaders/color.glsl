// sRGB transfer functions (IEC 61966-2-1). Scenes shade display-referred,
// sRGB-encoded colour, as Shadertoy shaders do; every pass that filters or
// blends works on linear light, and sRGB-encoded render targets
// (GL_SRGB8_ALPHA8 with GL_FRAMEBUFFER_SRGB) encode on write and decode on
// read.
vec3 foveate_linear(vec3 srgb) {
  vec3 c = clamp(srgb, 0.0, 1.0);
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}
vec3 foveate_srgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
