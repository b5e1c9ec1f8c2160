// A shading pass over a multisampled G-buffer (MSAA for mesh scenes): pixels
// whose samples all saw the same surface are shaded once; on edges every
// sample is shaded and the results averaged.
#include "color.glsl"
#include "pass_kit/footprint.glsl"
// No discard (see shade_main.frag): the pass's cover leaves out what it
// must not shade.
out vec4 o_color;
void main() {
  vec2 p = foveate_map(gl_FragCoord.xy);
#ifdef FOVEATE_FOOTPRINT
  foveate_footprint_px = foveate_spacing(gl_FragCoord.xy, p);
#endif
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
