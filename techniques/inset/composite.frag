// The foveal inset over the upscaled periphery, drawn only over the inset's
// rectangle (scissor) and blended by alpha in linear light: a vignette of
// weight 1 inside (radius - border), a smoothstep to 0 at the radius.
uniform sampler2D u_inset;
uniform vec4 u_inset_rect;  // x0, y0, w, h in screen pixels
uniform vec2 u_gaze_gl;     // pixels, origin bottom-left
uniform float u_radius;
uniform float u_border;
out vec4 o_color;
void main() {
  vec2 p = gl_FragCoord.xy;
  float d = distance(p, u_gaze_gl);
  float w = u_border > 0.0 ? 1.0 - smoothstep(u_radius - u_border, u_radius, d) : step(d, u_radius);
  vec2 iuv = (p - u_inset_rect.xy) / u_inset_rect.zw;
  o_color = vec4(texture(u_inset, iuv).rgb, w);
}
