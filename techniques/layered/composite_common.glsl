// Composites eccentricity layers in linear light: the outer layer everywhere,
// then each inner layer over it, fully out to its radius e_i and blended with a
// smoothstep over the band from e_i to e_i (1 + band) (Guenter et al.,
// Figure 3, with the band outside e_i so that a coarser layer only shows where
// its sampling meets the acuity model). Layers are sampled bilinearly.
uniform sampler2D u_layers[6];
uniform vec4 u_rects[6];    // x0, y0, w, h in screen pixels
uniform vec2 u_centres[6];  // unjittered gaze of each layer's render
uniform float u_radii[6];
uniform int u_count;
uniform float u_band;  // blend band width as a fraction of the radius
#ifdef FOVEATE_WARP
// Layers not updated this frame (half rate) on mesh scenes: the world point
// each of their pixels saw, and the camera they were rendered with. Compiled
// only into the variant used on frames that have such a layer (composite_warp.frag):
// llvmpipe would otherwise pay for the branch on every pixel.
uniform int u_warp[6];
uniform sampler2D u_positions[6];
uniform mat4 u_layer_view_proj[6];
uniform mat4 u_view_proj;  // this frame's camera
uniform vec2 u_frame_size;
#endif
out vec4 o_color;

vec3 layer(int i, vec2 p) {
  vec2 uv = (p - u_rects[i].xy) / u_rects[i].zw;
#ifdef FOVEATE_WARP
  if (u_warp[i] != 0) {
    // Reverse reprojection by the motion of the point found at p (one fixed-point step).
    vec4 x = vec4(texture(u_positions[i], uv).xyz, 1.0);
    vec4 now = u_view_proj * x, then = u_layer_view_proj[i] * x;
    if (now.w > 0.0 && then.w > 0.0) {
      vec2 q = p - (now.xy / now.w - then.xy / then.w) * 0.5 * u_frame_size;
      uv = (q - u_rects[i].xy) / u_rects[i].zw;
    }
  }
#endif
  return texture(u_layers[i], uv).rgb;
}

void main() {
  vec2 p = gl_FragCoord.xy;
  vec3 col = layer(u_count - 1, p);
  for (int i = u_count - 2; i >= 0; --i) {
    float r = u_radii[i];
    float d = distance(p, u_centres[i]);
    float w = u_band > 0.0 ? 1.0 - smoothstep(r, (1.0 + u_band) * r, d) : step(d, r);
    if (w > 0.0) col = mix(col, layer(i, p), w);
  }
  o_color = vec4(col, 1.0);
}
