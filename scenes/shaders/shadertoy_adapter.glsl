// Adapts Shadertoy's mainImage to foveate's shading function.
vec4 scene_shade(vec2 screen_px) {
  vec4 c = vec4(0.0, 0.0, 0.0, 1.0);
  mainImage(c, screen_px);
  return vec4(clamp(c.rgb, 0.0, 1.0), 1.0);
}
