// Screen <- the warped buffer (prefiltered, sharpen.frag), and the native
// disc around the gaze: what the resolve's regions read.
#include "marwarp/warp.glsl"
uniform sampler2D u_buffer;  // linear light
uniform sampler2D u_fovea;   // native pixels of u_fovea_rect
uniform vec4 u_fovea_rect;   // x0, y0, w, h in screen pixels (origin bottom-left)

vec3 native_pixel() {
  return texelFetch(u_fovea, ivec2(gl_FragCoord.xy - u_fovea_rect.xy), 0).rgb;
}

// One bilinear read of the buffer at this pixel.
vec3 buffer_colour() { return texture(u_buffer, warp_uv(gl_FragCoord.xy)).rgb; }
