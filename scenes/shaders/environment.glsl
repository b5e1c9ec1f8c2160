// The environment of the mesh scenes: sky gradient, a mountain range on the
// horizon and drifting clouds (also used for reflections).
vec3 environment(vec3 d, float time) {
  d = normalize(d);
  vec3 sky = mix(vec3(0.72, 0.8, 0.9), vec3(0.25, 0.45, 0.8), clamp(d.y * 1.8, 0.0, 1.0));
  float az = atan(d.z, d.x);
  float ridge = 0.06 + 0.04 * sin(az * 3.0) + 0.025 * sin(az * 7.0 + 1.3) + 0.012 * sin(az * 19.0);
  if (d.y < ridge && d.y > -0.02) {
    float snow = smoothstep(ridge - 0.02, ridge - 0.005, d.y);
    return mix(vec3(0.32, 0.36, 0.42), vec3(0.92), snow);
  }
  if (d.y > 0.0) {
    vec2 uv = d.xz / (d.y + 0.15) * 1.5 + vec2(time * 0.02, 0.0);
    float c = smoothstep(0.45, 0.75, fbm(vec3(uv, 0.0), 4));
    sky = mix(sky, vec3(1.0), c * 0.8);
  } else {
    sky = vec3(0.35, 0.33, 0.3);
  }
  return sky;
}
