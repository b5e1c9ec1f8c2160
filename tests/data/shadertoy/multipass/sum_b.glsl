// Buffer B adds up Buffer A of this frame (A runs before B): after frame k
// it holds 1 + 2 + ... + (k + 1).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  float a = texelFetch(iChannel0, ivec2(fragCoord), 0).r;
  fragColor = texelFetch(iChannel1, ivec2(fragCoord), 0) + vec4(a, 0.0, 0.0, 0.0);
}
