// A shading pass over a multisampled G-buffer (MSAA for mesh scenes): pixels
// whose samples all saw the same surface are shaded once; on edges every
// sample is shaded and the results averaged.
#include "color.glsl"
uniform vec4 u_keep_rect;  // x0, y0, x1, y1; empty = keep everything
out vec4 o_color;
void main() {
  vec2 p = foveate_map(gl_FragCoord.xy);
  if (u_keep_rect.z > u_keep_rect.x &&
      (p.x < u_keep_rect.x || p.y < u_keep_rect.y || p.x > u_keep_rect.z || p.y > u_keep_rect.w)) {
    discard;
  }
  vec3 c = vec3(0.0);
  if (scene_samples_differ(p)) {
    for (foveate_sample = 0; foveate_sample < FOVEATE_GBUFFER_SAMPLES; ++foveate_sample) c += foveate_linear(scene_shade(p).rgb);
    c /= float(FOVEATE_GBUFFER_SAMPLES);
  } else {
    foveate_sample = 0;
    c = foveate_linear(scene_shade(p).rgb);
  }
  o_color = vec4(c, 1.0);
}
