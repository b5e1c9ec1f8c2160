// "raymarch": an expensive ray-marched scene: a field of rounded columns, a
// twisted torus and metal spheres over rolling ground, with soft shadows,
// ambient occlusion, fog and one reflection bounce; the ground's checker is
// box-filtered over the spacing of the samples that shade it (footprint.glsl).
#include "camera.glsl"
#include "footprint.glsl"

// The angle between the camera rays of neighbouring pixels (radians), set
// by mainImage: with foveate_footprint_px, the samples' spacing at a hit.
float g_pixel_angle = 0.0;

float sd_round_box(vec3 p, vec3 b, float r) {
  vec3 q = abs(p) - b;
  return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float ground(vec3 p) {
  return p.y + 0.25 * sin(p.x * 0.7) * sin(p.z * 0.6) + 0.05 * sin(p.x * 3.1 + p.z * 2.3);
}

// A number in [0, 1) per grid cell from integer arithmetic alone, so that
// every GPU builds the same columns (a sine-based hash of the cell differs
// between drivers: their sin() of large arguments does).
float cell_random(vec2 cell) {
  uvec2 c = uvec2(ivec2(cell));
  uint h = c.x * 0x9E3779B1u + c.y * 0x85EBCA77u + 0x27D4EB2Fu;
  h = (h ^ (h >> 15)) * 0x2C1B3C6Du;
  h = (h ^ (h >> 12)) * 0x297A2D39u;
  h ^= h >> 15;
  return float(h >> 8) / 16777216.0;
}

vec2 map(vec3 p) {
  vec2 res = vec2(ground(p), 1.0);
  // Columns on a repeated grid, height varying per cell.
  vec2 cell = floor((p.xz + 2.0) / 4.0);
  vec3 q = p;
  q.xz = mod(p.xz + 2.0, 4.0) - 2.0;
  float hgt = 1.0 + 0.8 * cell_random(cell);
  float col = sd_round_box(q - vec3(0.0, hgt, 0.0), vec3(0.35, hgt, 0.35), 0.12);
  if (col < res.x && dot(cell, cell) > 2.0) res = vec2(col, 2.0);  // a clearing in the middle
  // A twisted torus at the centre.
  vec3 t = p - vec3(0.0, 1.6, 0.0);
  float a = t.y * 1.5;
  t.xz = mat2(cos(a), -sin(a), sin(a), cos(a)) * t.xz;
  vec2 tq = vec2(length(t.xz) - 1.2, t.y);
  float tor = length(tq) - 0.35 + 0.04 * sin(8.0 * atan(t.z, t.x));
  if (tor < res.x) res = vec2(tor, 3.0);
  // Metal spheres.
  for (int i = 0; i < 4; ++i) {
    float fi = float(i);
    vec3 c = vec3(3.0 * cos(fi * 1.57 + 0.3), 0.7, 3.0 * sin(fi * 1.57 + 0.3));
    float s = length(p - c) - 0.6;
    if (s < res.x) res = vec2(s, 4.0);
  }
  return res;
}

vec3 normal_at(vec3 p) {
  const vec2 e = vec2(0.0015, 0.0);
  return normalize(vec3(map(p + e.xyy).x - map(p - e.xyy).x, map(p + e.yxy).x - map(p - e.yxy).x,
                        map(p + e.yyx).x - map(p - e.yyx).x));
}

vec2 march(vec3 ro, vec3 rd) {
  float t = 0.02;
  for (int i = 0; i < 160; ++i) {
    vec2 h = map(ro + rd * t);
    if (abs(h.x) < 0.0008 * t) return vec2(t, h.y);
    t += h.x * 0.8;
    if (t > 60.0) break;
  }
  return vec2(-1.0, 0.0);
}

float soft_shadow(vec3 ro, vec3 rd) {
  float res = 1.0, t = 0.03;
  for (int i = 0; i < 48; ++i) {
    float h = map(ro + rd * t).x;
    res = min(res, 10.0 * h / t);
    t += clamp(h, 0.02, 0.4);
    if (res < 0.001 || t > 12.0) break;
  }
  return clamp(res, 0.0, 1.0);
}

float occlusion(vec3 p, vec3 n) {
  float occ = 0.0, w = 1.0;
  for (int i = 1; i <= 5; ++i) {
    float d = 0.06 * float(i);
    occ += w * (d - map(p + n * d).x);
    w *= 0.7;
  }
  return clamp(1.0 - 2.5 * occ, 0.0, 1.0);
}

vec3 sky(vec3 rd) {
  return mix(vec3(0.75, 0.82, 0.9), vec3(0.25, 0.45, 0.8), clamp(rd.y * 1.5, 0.0, 1.0));
}

// `w`: the samples' spacing on the surface (world units).
vec3 material(float id, vec3 p, float w) {
  if (id < 1.5) {
    // Half-unit squares, box-filtered over w: the ground's checker edges
    // would otherwise alias into stairs wherever the samples are sparse.
    vec2 sq = filtered_square(p.xz * 2.0, w * 2.0);
    return mix(vec3(0.32, 0.28, 0.22), vec3(0.45, 0.4, 0.3), 0.5 - 0.5 * sq.x * sq.y);
  }
  if (id < 2.5) return vec3(0.7, 0.55, 0.4);
  if (id < 3.5) return vec3(0.8, 0.2, 0.15);
  return vec3(0.85);
}

// `travelled`: the ray's length before ro (a reflection's from the eye).
vec3 shade_hit(vec3 ro, vec3 rd, vec2 hit, float travelled, out vec3 pos, out vec3 nor) {
  pos = ro + rd * hit.x;
  nor = normal_at(pos);
  // The samples' spacing on the surface: the rays' spread over the distance,
  // widened on a slant by its square root (the footprint's two axes' mean).
  float w = foveate_footprint_px * g_pixel_angle * (travelled + hit.x) /
            sqrt(max(abs(dot(nor, rd)), 0.05));
  vec3 sun = normalize(vec3(0.6, 0.7, 0.35));
  float dif = max(dot(nor, sun), 0.0) * soft_shadow(pos + nor * 0.01, sun);
  float occ = occlusion(pos, nor);
  float spe = pow(max(dot(reflect(rd, nor), sun), 0.0), 32.0) * dif;
  vec3 alb = material(hit.y, pos, w);
  vec3 col = alb * (1.6 * dif * vec3(1.0, 0.95, 0.85) + 0.35 * occ * vec3(0.5, 0.6, 0.8)) + spe;
  return mix(col, sky(rd), 1.0 - exp(-0.0015 * hit.x * hit.x));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 ro;
  vec3 rd = foveate_ray(fragCoord, ro);
  vec3 ro1;
  g_pixel_angle = length(foveate_ray(fragCoord + vec2(1.0, 0.0), ro1) - rd);
  vec2 hit = march(ro, rd);
  vec3 col = sky(rd);
  if (hit.x > 0.0) {
    vec3 pos, nor;
    col = shade_hit(ro, rd, hit, 0.0, pos, nor);
    if (hit.y > 3.5) {  // metal: one reflection bounce
      vec3 rr = reflect(rd, nor);
      vec2 h2 = march(pos + nor * 0.02, rr);
      vec3 p2, n2;
      vec3 refl = h2.x > 0.0 ? shade_hit(pos + nor * 0.02, rr, h2, hit.x, p2, n2) : sky(rr);
      col = mix(col, refl, 0.6);
    }
  }
  fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
