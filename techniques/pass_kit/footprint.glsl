// The spacing of a mapping's samples on the screen, for scenes that filter
// their materials by it (FOVEATE_FOOTPRINT, scenes/shaders/footprint.glsl):
// how far apart, in screen pixels, the mapping puts the samples of buffer
// positions one texel apart, the wider of the two axes (a texel must not
// alias along either). Finite differences rather than derivatives: they mean
// the same in a packed pass, whose neighbouring fragments are unrelated
// texels, and across a polar buffer's wrap. Included after the mapping.
float foveate_spacing(vec2 c, vec2 at) {
  return max(length(foveate_map(c + vec2(1.0, 0.0)) - at), length(foveate_map(c + vec2(0.0, 1.0)) - at));
}
