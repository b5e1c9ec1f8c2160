// What GL_NV_shading_rate_image leaves, made from a full-resolution frame
// (vrs.simulate_driver, for renderers without the extension): every pixel of
// a coarse fragment gets the colour shaded at the fragment's sample point,
// its centre (a pixel corner for an even size: the mean of the pixels around
// it, in linear light) or, on mesh scenes, the G-buffer pixel at the centre.
uniform sampler2D u_full;   // native, shaded at every pixel (bilinear)
uniform usampler2D u_shade;  // per tile: the rate to simulate (index into the rates, GL rows)
uniform vec2 u_rates[7];
uniform int u_tile;
uniform float u_sample_offset;  // 0.5 on mesh scenes, else 0 (hardware_reconstruct.frag)
out vec4 o_color;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  ivec2 rate = ivec2(u_rates[texelFetch(u_shade, px / u_tile, 0).r]);
  vec2 size = vec2(textureSize(u_full, 0));
  vec2 point = vec2(px / rate * rate) + 0.5 * vec2(rate) +
               vec2(greaterThan(rate, ivec2(1))) * u_sample_offset;
  o_color = vec4(texture(u_full, clamp(point, vec2(0.5), size - 0.5) / size).rgb, 1.0);
}
