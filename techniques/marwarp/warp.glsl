// The radial warp of core/acuity_warp.hpp, both ways. Screen positions are
// pixels (origin bottom-left), buffer positions texels (u: the column, a
// distance from the gaze; v: the row, an angle):
//   buffer -> screen: E = ((m E0 + w0) exp(m u / 2) - w0) / m, r = F tan E;
//   screen -> buffer: u = 2 / m ln((m E + w0) / (m E0 + w0)), E = atan(r / F),
// angles in degrees, v = angle / (2 pi) rows.
uniform vec2 u_warp_gaze;    // screen pixels
uniform vec4 u_warp;         // F (pixels), m, w0 (degrees), m E0 + w0
// The texture's width (columns), the rows, the texture's height (at least
// rows + 1: row `rows` repeats row 0).
uniform vec3 u_warp_buffer;
const float WARP_DEG = 57.2957795131;
const float WARP_TWO_PI = 6.28318530718;

vec2 warp_to_screen(vec2 texel) {
  float e = (u_warp.w * exp(0.5 * u_warp.y * texel.x) - u_warp.z) / u_warp.y;
  float r = u_warp.x * tan(clamp(e, 0.0, 89.0) / WARP_DEG);
  float a = texel.y * WARP_TWO_PI / u_warp_buffer.y;
  return u_warp_gaze + r * vec2(cos(a), sin(a));
}

// Normalised texture coordinates of a screen position. A bilinear read
// within half a row of the angle's wrap reads the last row and row `rows`,
// which repeats row 0.
vec2 warp_uv(vec2 screen) {
  vec2 d = screen - u_warp_gaze;
  float e = atan(length(d) / u_warp.x) * WARP_DEG;
  float u = 2.0 / u_warp.y * log((u_warp.y * e + u_warp.z) / u_warp.w);
  float a = atan(d.y, d.x);
  if (a < 0.0) a += WARP_TWO_PI;
  float row = a / WARP_TWO_PI * u_warp_buffer.y;
  if (row < 0.5) row += u_warp_buffer.y;
  return vec2(u / u_warp_buffer.x, row / u_warp_buffer.z);
}
