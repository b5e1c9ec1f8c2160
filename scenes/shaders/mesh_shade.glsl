// Deferred lighting of mesh files: a sun, six coloured point lights around the
// model, hemispherical ambient and environment reflections.
#include "noise.glsl"
#include "environment.glsl"
#include "deferred_common.glsl"
uniform vec4 u_lights[6];        // position xyz, range w
uniform vec3 u_light_colors[6];

vec4 scene_shade(vec2 screen_px) {
  Surface s = fetch_surface(screen_px);
  if (!s.hit) return vec4(environment(s.view_dir, u_time), 1.0);
  vec3 n = s.normal;
  vec3 v = -s.view_dir;
  vec3 sun = normalize(vec3(0.5, 0.8, 0.3));
  float shin = mix(8.0, 128.0, s.gloss);
  vec3 col = s.albedo * (0.25 * mix(vec3(0.35, 0.3, 0.25), vec3(0.6, 0.7, 0.9), 0.5 + 0.5 * n.y));
  col += s.albedo * vec3(1.0, 0.95, 0.85) * max(dot(n, sun), 0.0);
  col += s.gloss * pow(max(dot(n, normalize(sun + v)), 0.0), shin);
  for (int i = 0; i < 6; ++i) {
    vec3 l = u_lights[i].xyz - s.position;
    float d = length(l);
    l /= d;
    float att = 1.0 / (1.0 + (d * d) / (u_lights[i].w * u_lights[i].w));
    col += att * u_light_colors[i] * (s.albedo * max(dot(n, l), 0.0) +
                                      s.gloss * pow(max(dot(n, normalize(l + v)), 0.0), shin));
  }
  vec3 r = reflect(s.view_dir, n);
  float fres = 0.04 + 0.96 * pow(1.0 - max(dot(n, v), 0.0), 5.0);
  col = mix(col, environment(r, u_time), s.gloss * fres);
  return vec4(pow(clamp(col, 0.0, 1.0), vec3(0.4545)), 1.0);
}
