// A heavy Shadertoy-style shader for benchmarks (written for foveate): a
// power-8 Mandelbulb, sphere-traced with a distance estimate, soft shadows
// and ambient occlusion, the camera orbiting slowly. Every pixel costs about
// the same, so the frame time is proportional to the pixels shaded.

const int kIterations = 8;
const int kSteps = 160;

// Distance estimate of the Mandelbulb (power 8) and an orbit trap for colour.
float bulb(vec3 p, out float trap) {
  vec3 z = p;
  float dr = 1.0;
  float r = 0.0;
  trap = 1e10;
  for (int i = 0; i < kIterations; ++i) {
    r = length(z);
    if (r > 2.0) break;
    float theta = acos(clamp(z.z / r, -1.0, 1.0)) * 8.0;
    float phi = atan(z.y, z.x) * 8.0;
    float r7 = pow(r, 7.0);
    dr = r7 * 8.0 * dr + 1.0;
    z = r7 * r * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta)) + p;
    trap = min(trap, dot(z, z));
  }
  return 0.5 * log(r) * r / dr;
}

float dist(vec3 p) {
  float t;
  return bulb(p, t);
}

vec3 normal_at(vec3 p) {
  const vec2 e = vec2(1e-3, 0.0);
  return normalize(vec3(dist(p + e.xyy) - dist(p - e.xyy), dist(p + e.yxy) - dist(p - e.yxy),
                        dist(p + e.yyx) - dist(p - e.yyx)));
}

float shadow(vec3 p, vec3 l) {
  float s = 1.0, t = 0.01;
  for (int i = 0; i < 40; ++i) {
    float h = dist(p + l * t);
    s = min(s, 12.0 * h / t);
    t += clamp(h, 0.005, 0.2);
    if (s < 0.01 || t > 3.0) break;
  }
  return clamp(s, 0.0, 1.0);
}

float occlusion(vec3 p, vec3 n) {
  float o = 0.0, w = 1.0;
  for (int i = 1; i <= 5; ++i) {
    float h = 0.03 * float(i);
    o += w * (h - dist(p + n * h));
    w *= 0.6;
  }
  return clamp(1.0 - 4.0 * o, 0.0, 1.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  float a = 0.15 * iTime;
  vec3 eye = vec3(2.6 * sin(a), 0.9, 2.6 * cos(a));
  vec3 fwd = normalize(-eye);
  vec3 right = normalize(cross(fwd, vec3(0.0, 1.0, 0.0)));
  vec3 up = cross(right, fwd);
  vec3 dir = normalize(fwd * 1.8 + uv.x * right + uv.y * up);

  vec3 sky = mix(vec3(0.55, 0.65, 0.8), vec3(0.1, 0.15, 0.3), 0.5 + 0.5 * dir.y);
  vec3 col = sky;
  float t = 0.0;
  float trap = 0.0;
  bool hit = false;
  for (int i = 0; i < kSteps; ++i) {
    vec3 p = eye + dir * t;
    float d = bulb(p, trap);
    if (d < 0.0005 * t) {
      hit = true;
      break;
    }
    t += d;
    if (t > 6.0) break;
  }
  if (hit) {
    vec3 p = eye + dir * t;
    vec3 n = normal_at(p);
    vec3 l = normalize(vec3(0.6, 0.8, 0.3));
    vec3 base = mix(vec3(0.9, 0.55, 0.25), vec3(0.25, 0.5, 0.9), clamp(trap * 0.6, 0.0, 1.0));
    float diff = max(dot(n, l), 0.0) * shadow(p + n * 0.002, l);
    float ao = occlusion(p, n);
    float spec = pow(max(dot(reflect(-l, n), -dir), 0.0), 24.0);
    col = base * (0.15 * ao + 0.9 * diff) + 0.3 * spec * diff + 0.1 * sky * ao;
  }
  fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);
}
