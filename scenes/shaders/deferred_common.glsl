// Reading the mesh scenes' G-buffer at a screen position, and the camera ray.
uniform sampler2D u_g_albedo;
uniform sampler2D u_g_normal;
uniform sampler2D u_g_position;
uniform vec4 u_g_rect;        // the prepass view: x0, y0, w, h in screen pixels
uniform vec2 u_screen;
uniform mat4 u_inv_view_proj; // of the full frame
uniform vec3 u_cam_pos;
uniform float u_time;

struct Surface {
  bool hit;
  vec3 albedo;
  float material;
  vec3 normal;
  float gloss;
  vec3 position;
  vec3 view_dir;  // from the camera
};

Surface fetch_surface(vec2 screen_px) {
  Surface s;
  vec4 ndc = vec4(screen_px / u_screen * 2.0 - 1.0, 1.0, 1.0);
  vec4 far = u_inv_view_proj * ndc;
  s.view_dir = normalize(far.xyz / far.w - u_cam_pos);
  ivec2 size = textureSize(u_g_albedo, 0);
  ivec2 t = ivec2(floor((screen_px - u_g_rect.xy) / u_g_rect.zw * vec2(size)));
  s.hit = false;
  if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) return s;
  vec4 p = texelFetch(u_g_position, t, 0);
  if (p.w < 0.5) return s;
  vec4 a = texelFetch(u_g_albedo, t, 0);
  vec4 n = texelFetch(u_g_normal, t, 0);
  s.hit = true;
  s.albedo = a.rgb;
  s.material = floor(a.a * 255.0 + 0.5);
  s.normal = normalize(n.xyz);
  s.gloss = n.w;
  s.position = p.xyz;
  return s;
}

// For temporal reprojection (Scene::view_projection): the world point seen at
// a screen position; background is a far point along the view ray.
vec3 scene_world_position(vec2 screen_px) {
  Surface s = fetch_surface(screen_px);
  return s.hit ? s.position : u_cam_pos + s.view_dir * 1.0e4;
}
