// Periphery upscaled with a slight tent blur, foveal inset blended over it
// with a vignette: weight 1 inside (radius - border), smoothstep to 0 at radius.
uniform sampler2D u_periphery;
uniform sampler2D u_inset;
uniform int u_has_inset;
uniform vec4 u_inset_rect;  // x0, y0, w, h in screen pixels
uniform vec2 u_gaze_gl;  // pixels, origin bottom-left
uniform float u_radius;
uniform float u_border;
uniform float u_blur;       // in periphery texels
uniform vec2 u_screen;
out vec4 o_color;
void main() {
  vec2 p = gl_FragCoord.xy;
  vec2 uv = p / u_screen;
  vec2 texel = u_blur / vec2(textureSize(u_periphery, 0));
  vec3 col = 0.25 * texture(u_periphery, uv).rgb;
  col += 0.1875 * (texture(u_periphery, uv + vec2(texel.x, 0.0)).rgb + texture(u_periphery, uv - vec2(texel.x, 0.0)).rgb +
                   texture(u_periphery, uv + vec2(0.0, texel.y)).rgb + texture(u_periphery, uv - vec2(0.0, texel.y)).rgb);
  if (u_has_inset != 0) {
    float d = distance(p, u_gaze_gl);
    float w = u_border > 0.0 ? 1.0 - smoothstep(u_radius - u_border, u_radius, d) : step(d, u_radius);
    if (w > 0.0) {
      vec2 iuv = (p - u_inset_rect.xy) / u_inset_rect.zw;
      col = mix(col, texture(u_inset, iuv).rgb, w);
    }
  }
  o_color = vec4(col, 1.0);
}
