// A Shadertoy shader as it would run on shadertoy.com: iChannel0 shown on the
// left half, and a disc drawn where the mouse is.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.xy;
  vec3 col = vec3(0.1, 0.1, 0.1);
  if (uv.x < 0.5) col = texture(iChannel0, vec2(uv.x * 2.0, uv.y)).rgb;
  if (iMouse.z > 0.0 && length(fragCoord - iMouse.xy) < 6.0) col = vec3(1.0, 1.0, 0.0);
  fragColor = vec4(col, 1.0);
}
