// Deferred shading of the guenter scene: procedural materials evaluated per
// pixel from the world position (the expensive part, as in the paper), a sun
// with specular highlights, hemispherical ambient, environment reflections and
// fog into the environment.
#include "noise.glsl"
#include "environment.glsl"
#include "deferred_common.glsl"

vec3 terrain_material(vec3 p, inout vec3 n) {
  // The paper's terrain shading dominated its frame time ("Cheap Terrain" in
  // its Table 1 cut 23.6 ms to 6.6 ms): many octaves of noise per pixel.
  float broad = fbm(p * 0.08, 6);
  float fine = fbm(p * 1.3, 8);
  // Bump the normal with the gradient of the fine noise.
  const float e = 0.05;
  vec3 g = vec3(fbm((p + vec3(e, 0, 0)) * 1.3, 7), fbm((p + vec3(0, e, 0)) * 1.3, 7), fbm((p + vec3(0, 0, e)) * 1.3, 7)) -
           vec3(fbm(p * 1.3, 7));
  n = normalize(n - 1.5 * g);
  vec3 grass = mix(vec3(0.16, 0.3, 0.08), vec3(0.3, 0.42, 0.12), fine);
  vec3 rock = mix(vec3(0.35, 0.32, 0.28), vec3(0.55, 0.5, 0.45), fine);
  float slope = 1.0 - n.y;
  return mix(grass, rock, smoothstep(0.25, 0.5, slope + 0.3 * broad - 0.15));
}

vec3 object_material(float id, vec3 albedo, vec3 p) {
  if (id < 2.5) return albedo * (0.8 + 0.2 * fbm(p * 3.0, 4));                        // clay
  if (id < 3.5) {                                                                      // marble
    float v = 0.5 + 0.5 * sin(p.x * 5.0 + 8.0 * fbm(p * 1.5, 6));
    return mix(vec3(0.9, 0.88, 0.85), albedo * 0.4, pow(v, 3.0));
  }
  if (id < 4.5) {                                                                      // wood
    float r = fract(length(p.xz * 3.0) + 2.0 * fbm(p * 2.0, 5));
    return mix(vec3(0.45, 0.28, 0.12), vec3(0.7, 0.5, 0.3), smoothstep(0.2, 0.8, r));
  }
  if (id < 5.5) {                                                                      // checker
    vec3 q = floor(p * 4.0);
    return mod(q.x + q.y + q.z, 2.0) < 1.0 ? albedo : vec3(0.95);
  }
  if (id < 6.5) return albedo;                                                         // glossy plastic
  if (id < 7.5) return vec3(0.9);                                                      // chrome
  return vec3(1.0, 0.78, 0.35) * (0.9 + 0.1 * sin(p.y * 80.0 + 4.0 * fbm(p * 6.0, 3)));  // brushed gold
}

vec4 scene_shade(vec2 screen_px) {
  Surface s = fetch_surface(screen_px);
  if (!s.hit) return vec4(environment(s.view_dir, u_time), 1.0);
  vec3 n = s.normal;
  vec3 albedo = s.material < 1.5 ? terrain_material(s.position, n) : object_material(s.material, s.albedo, s.position);
  vec3 v = -s.view_dir;
  vec3 sun = normalize(vec3(0.45, 0.75, 0.35));
  float gloss = s.material >= 6.5 ? 0.9 : s.gloss;
  float shin = mix(6.0, 200.0, gloss);
  vec3 col = albedo * (0.3 * mix(vec3(0.3, 0.28, 0.25), vec3(0.55, 0.65, 0.85), 0.5 + 0.5 * n.y));
  col += albedo * vec3(1.0, 0.95, 0.85) * max(dot(n, sun), 0.0);
  col += gloss * pow(max(dot(n, normalize(sun + v)), 0.0), shin);
  vec3 r = reflect(s.view_dir, n);
  float fres = 0.04 + 0.96 * pow(1.0 - max(dot(n, v), 0.0), 5.0);
  float metal = s.material >= 6.5 ? 0.85 : 0.0;
  col = mix(col, environment(r, u_time) * (metal > 0.0 ? albedo : vec3(1.0)), max(metal, gloss * fres));
  float dist = length(s.position - u_cam_pos);
  col = mix(col, environment(s.view_dir, u_time), 1.0 - exp(-0.00006 * dist * dist));
  return vec4(pow(clamp(col, 0.0, 1.0), vec3(0.4545)), 1.0);
}
