// Written for the VS Code Shadertoy extension, which names channels in the
// shader: foveate blanks that line (with a warning) and takes the channel
// from --channel. Left half: iChannel0; right half: blue.
#iChannel0 "file://quadrants.png"
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.xy;
  fragColor = uv.x < 0.5 ? texture(iChannel0, vec2(uv.x * 2.0, uv.y)) : vec4(0.0, 0.0, 1.0, 1.0);
}
