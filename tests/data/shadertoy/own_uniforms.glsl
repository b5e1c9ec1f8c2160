// A port that declares Shadertoy's inputs itself, as many hosts need: the
// declarations stay, and foveate sets them. At --time 1 and 64x36: red =
// iTime / 2, green = iResolution.x / 128, blue = iChannelResolution[0].x / 32
// (quadrants.png is 16 pixels wide).
uniform vec3 iResolution;
uniform float iTime;
uniform vec3 iChannelResolution[4];
uniform sampler2D iChannel0;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  fragColor = vec4(iTime / 2.0, iResolution.x / 128.0, iChannelResolution[0].x / 32.0, 1.0)
              + 0.0 * texture(iChannel0, vec2(0.5));
}
