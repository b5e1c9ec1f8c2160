// The periphery's slight tent blur, at the periphery's own resolution (the
// composite then reads it with one bilinear fetch per screen pixel): a centre
// weight of 1/4 and four taps of 3/16 at u_blur texels, in linear light.
in vec2 v_uv;
uniform sampler2D u_periphery;
uniform float u_blur;  // in periphery texels
out vec4 o_color;
void main() {
  vec2 texel = u_blur / vec2(textureSize(u_periphery, 0));
  vec3 col = 0.25 * texture(u_periphery, v_uv).rgb;
  col += 0.1875 * (texture(u_periphery, v_uv + vec2(texel.x, 0.0)).rgb +
                   texture(u_periphery, v_uv - vec2(texel.x, 0.0)).rgb +
                   texture(u_periphery, v_uv + vec2(0.0, texel.y)).rgb +
                   texture(u_periphery, v_uv - vec2(0.0, texel.y)).rgb);
  o_color = vec4(col, 1.0);
}
