// "cheap": a smooth, inexpensive scene: a sky gradient and a lit floor with a
// few soft discs. Little to save, little to lose.
#include "camera.glsl"

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 ro;
  vec3 rd = foveate_ray(fragCoord, ro);
  vec3 col = mix(vec3(0.9, 0.85, 0.75), vec3(0.3, 0.5, 0.85), clamp(rd.y * 2.0 + 0.3, 0.0, 1.0));
  if (rd.y < 0.0) {
    vec2 p = ro.xz + rd.xz * (-ro.y / rd.y);
    float discs = 0.0;
    for (int i = 0; i < 3; ++i) {
      vec2 c = vec2(2.0 * cos(float(i) * 2.1), 2.0 * sin(float(i) * 2.1));
      discs += smoothstep(1.0, 0.6, length(p - c));
    }
    vec3 ground = mix(vec3(0.55, 0.6, 0.5), vec3(0.9, 0.5, 0.3), clamp(discs, 0.0, 1.0));
    col = mix(vec3(0.8, 0.8, 0.78), ground, exp(-0.004 * dot(p, p)));
  }
  fragColor = vec4(col, 1.0);
}
