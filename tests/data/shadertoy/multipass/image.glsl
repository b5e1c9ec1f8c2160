// The Image pass of counter.json: red = Buffer A / 10 (frames so far / 10),
// green = Buffer B / 100, blue = iFrame / 10; the left eighth shows the
// image channel (iChannel2) instead.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.xy;
  if (uv.x < 0.125) {
    fragColor = texture(iChannel2, vec2(uv.x * 8.0, uv.y));
    return;
  }
  float a = texture(iChannel0, uv).r;
  float b = texture(iChannel1, uv).r;
  fragColor = vec4(a / count_scale(), b / 100.0, float(iFrame) / 10.0, 1.0);
}
