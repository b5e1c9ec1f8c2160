// Reconstruction, last pass (see filter.glsl), where the native fovea fades
// into the filtered image: region 0, where no quad is dropped, is the shaded
// frame itself (native) out to the fovea's radius, then fades to the filtered
// image over the blend band. Drawn over the band only when the target can be
// split (reconstruct_fovea.frag inside, reconstruct_outer.frag beyond), over
// the whole screen when not.
#include "checkerboard/pattern.glsl"
#include "checkerboard/filtered.glsl"
uniform sampler2D u_frame;
uniform vec2 u_blend;  // radius of the native fovea, width of the blend band (pixels)
layout(early_fragment_tests) in;
out vec4 o_color;
void main() {
  ivec2 ip = ivec2(gl_FragCoord.xy);
  float w = 1.0;
  if (pattern_region(gl_FragCoord.xy) == 0) {
    float d = distance(pattern_top_left(gl_FragCoord.xy), u_gaze_top_left);
    w = u_blend.y > 0.0 ? smoothstep(u_blend.x, u_blend.x + u_blend.y, d) : 0.0;
  }
  vec3 native = texelFetch(u_frame, ip, 0).rgb;
  if (w <= 0.0) {
    o_color = vec4(native, 1.0);
    return;
  }
  vec4 s = filtered_sums(gl_FragCoord.xy);
  o_color = vec4(mix(native, s.a > 1e-6 ? s.rgb / s.a : native, w), 1.0);
}
