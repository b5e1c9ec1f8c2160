// Adapts Shadertoy's mainImage to foveate's shading function. Every name
// here has the foveate_ prefix: the user's code above may #define short
// names (c, o, col) that would otherwise replace them.
vec4 scene_shade(vec2 foveate_screen_px) {
  vec4 foveate_color = vec4(0.0, 0.0, 0.0, 1.0);
  mainImage(foveate_color, foveate_screen_px);
  return vec4(clamp(foveate_color.rgb, 0.0, 1.0), 1.0);
}
