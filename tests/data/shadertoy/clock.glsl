// iDate as colours: left half (year - 2000) / 50, month (from 0) / 20,
// day / 40; right half: the time of day / 86400 in every channel.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  if (fragCoord.x < iResolution.x * 0.5)
    fragColor = vec4((iDate.x - 2000.0) / 50.0, iDate.y / 20.0, iDate.z / 40.0, 1.0);
  else
    fragColor = vec4(vec3(iDate.w / 86400.0), 1.0);
}
