// Primary ray through a screen position for the built-in scenes' camera.
vec3 foveate_ray(vec2 frag, out vec3 origin) {
  origin = foveate_cam_pos;
  vec3 fw = normalize(foveate_cam_target - foveate_cam_pos);
  // World up is +y; looking straight down or up (parallel to it) the screen's
  // top points along -z or +z, as camera_up() in camera_path.cpp does.
  vec3 world_up = vec3(0.0, 1.0, 0.0);
  if (length(cross(fw, world_up)) < 1e-4) world_up = vec3(0.0, 0.0, fw.y < 0.0 ? -1.0 : 1.0);
  vec3 rt = normalize(cross(fw, world_up));
  vec3 up = cross(rt, fw);
  float h = tan(radians(foveate_cam_fov) * 0.5);
  vec2 p = (2.0 * frag - iResolution.xy) / iResolution.y;
  return normalize(fw + h * (p.x * rt + p.y * up));
}
