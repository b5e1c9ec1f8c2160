// Primary ray through a screen position for the built-in scenes' camera.
vec3 foveate_ray(vec2 frag, out vec3 origin) {
  origin = foveate_cam_pos;
  vec3 fw = normalize(foveate_cam_target - foveate_cam_pos);
  vec3 rt = normalize(cross(fw, vec3(0.0, 1.0, 0.0)));
  vec3 up = cross(rt, fw);
  float h = tan(radians(foveate_cam_fov) * 0.5);
  vec2 p = (2.0 * frag - iResolution.xy) / iResolution.y;
  return normalize(fw + h * (p.x * rt + p.y * up));
}
