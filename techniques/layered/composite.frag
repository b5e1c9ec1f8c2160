// Composites eccentricity layers in linear light: the outer layer everywhere,
// then each inner layer over it, fully out to its radius e_i and blended with a
// smoothstep over the band from e_i to e_i (1 + band) (Guenter et al.,
// Figure 3, with the band outside e_i so that a coarser layer only shows where
// its sampling meets the acuity model). Layers are sampled bilinearly; a layer
// shown stale has been warped to this frame first (warp.frag).
uniform sampler2D u_layers[6];
uniform vec4 u_rects[6];    // x0, y0, w, h in screen pixels
uniform vec2 u_centres[6];  // unjittered gaze of each layer's render
uniform float u_radii[6];
uniform int u_count;
uniform int u_first;   // the innermost layer that can show in this region (0 = all)
uniform float u_band;  // blend band width as a fraction of the radius
layout(early_fragment_tests) in;
out vec4 o_color;

vec3 layer(int i, vec2 p) {
  vec2 uv = (p - u_rects[i].xy) / u_rects[i].zw;
  return texture(u_layers[i], uv).rgb;
}

void main() {
  vec2 p = gl_FragCoord.xy;
  vec3 col = layer(u_count - 1, p);
  for (int i = u_count - 2; i >= u_first; --i) {
    float r = u_radii[i];
    float d = distance(p, u_centres[i]);
    float w = u_band > 0.0 ? 1.0 - smoothstep(r, (1.0 + u_band) * r, d) : step(d, r);
    if (w > 0.0) col = mix(col, layer(i, p), w);
  }
  o_color = vec4(col, 1.0);
}
