// Temporal resolve of a layer in screen space (scenes without depth): the
// history is where the same screen position was.
#include "layered/temporal_common.glsl"
void main() {
  vec2 size = vec2(textureSize(u_sample, 0));
  o_color = foveate_temporal(u_rect.xy + gl_FragCoord.xy * (u_rect.zw / size));
}
