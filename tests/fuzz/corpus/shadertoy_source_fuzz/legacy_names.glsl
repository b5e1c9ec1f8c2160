// Legacy names a shader may use unchanged: texture2D and textureCube (GLSL
// 1.x), iGlobalTime (Shadertoy's old iTime), iChannelTime, iSampleRate.
// Left half: iChannel0 through texture2D. Right half, top: the inputs as
// colours (at --time 1: 0.5, 0.5, 0.25). Bottom: textureCube on the 2D
// channel, read as a panorama: direction (0, 1, 1) is its top-right quarter.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.xy;
  if (uv.x < 0.5) {
    fragColor = texture2D(iChannel0, vec2(uv.x * 2.0, uv.y));
  } else if (uv.y > 0.5) {
    fragColor = vec4(iGlobalTime / 2.0, iSampleRate / 88200.0, iChannelTime[0] / 4.0, 1.0);
  } else {
    fragColor = textureCube(iChannel0, vec3(0.0, 1.0, 1.0));
  }
}
