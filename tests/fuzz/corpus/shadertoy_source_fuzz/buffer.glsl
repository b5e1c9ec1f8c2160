// Buffer A counts frames: its own last frame (iChannel0) plus one. After
// frame k (from 0) every pixel holds k + 1.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  fragColor = texelFetch(iChannel0, ivec2(fragCoord), 0) + vec4(1.0, 0.0, 0.0, 0.0);
}
