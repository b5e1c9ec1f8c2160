// Reading the packed quads' targets (block 1; checkerboard.cpp): texel i of a
// quad's target holds GL pixel 2 i + offset. A read at a pixel's own position
// is bilinear: its own sample where the pixel is that quad's, the mean of the
// nearest ones between them elsewhere. A read is divided by its alpha, the
// weight of shaded texels in it: 1, since the passes' rectangles hold every
// texel a read reaches (checkerboard.cpp), and no read counts a texel that
// was never shaded as black.
uniform sampler2D u_quad0;
uniform vec2 u_offset0;  // quad 0's pixel in each 2x2 block of GL pixels

vec4 read_quad(sampler2D quad, vec2 centre, vec2 offset) {
  return texture(quad, (0.5 * (centre - offset - 0.5) + 0.5) / vec2(textureSize(quad, 0)));
}

vec3 mean_of(vec4 sum) { return sum.rgb / max(sum.a, 1e-6); }
