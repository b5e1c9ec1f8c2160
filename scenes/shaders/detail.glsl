// "detail": fine, high-contrast detail everywhere, the worst case for
// peripheral aliasing: a checkered floor to the horizon, thin grid lines,
// and a zone plate (rings whose frequency rises with radius) on the sky.
#include "camera.glsl"

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 ro;
  vec3 rd = foveate_ray(fragCoord, ro);
  vec3 col;
  if (rd.y < -0.001) {
    float t = -ro.y / rd.y;
    vec2 p = ro.xz + rd.xz * t;
    float check = mod(floor(p.x * 2.0) + floor(p.y * 2.0), 2.0);
    vec2 g = abs(fract(p * 8.0) - 0.5);
    float line = step(0.46, max(g.x, g.y));
    col = mix(vec3(0.08), vec3(0.95), check);
    col = mix(col, vec3(0.9, 0.1, 0.1), line);
  } else {
    // Zone plate in direction space: cos(k r^2).
    vec2 d = rd.xz / max(rd.y, 0.05) + vec2(0.0, 0.0);
    float r2 = dot(rd.xy, rd.xy);
    float z = 0.5 + 0.5 * cos(900.0 * r2);
    col = mix(vec3(0.1, 0.1, 0.3), vec3(1.0, 1.0, 0.9), z);
    col *= 0.7 + 0.3 * step(0.5, fract(d.x * 4.0));
  }
  fragColor = vec4(col, 1.0);
}
