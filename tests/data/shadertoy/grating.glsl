// A fine black-and-white grating (period 1.37 px across, 2.91 px down): far
// beyond what any foveated periphery resolves. Its mean linear luminance is
// 0.5, which in sRGB codes is 188, not 128.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  float v = step(0.5, fract(fragCoord.x / 1.37 + fragCoord.y / 2.91));
  fragColor = vec4(vec3(v), 1.0);
}
