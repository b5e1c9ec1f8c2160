// Reading the mesh scenes' G-buffer at a screen position, and the camera ray.
#ifdef FOVEATE_GBUFFER_SAMPLES
// Multisampled G-buffer (View::samples > 1): the shading main picks the sample.
uniform sampler2DMS u_g_albedo;
uniform sampler2DMS u_g_normal;
uniform sampler2DMS u_g_position;
int foveate_sample = 0;
#define FOVEATE_FETCH(tex, t) texelFetch(tex, t, foveate_sample)
#define FOVEATE_SIZE(tex) textureSize(tex)
#else
uniform sampler2D u_g_albedo;
uniform sampler2D u_g_normal;
uniform sampler2D u_g_position;
#define FOVEATE_FETCH(tex, t) texelFetch(tex, t, 0)
#define FOVEATE_SIZE(tex) textureSize(tex, 0)
#endif
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

// The G-buffer texel (of a G-buffer of `size` texels over u_g_rect) under a
// screen position. A position exactly on a texel border (a coarse fragment's
// centre under variable-rate shading) must fall on the same side on every
// GPU; drivers that divide through a reciprocal put some a hair below it.
// The nudge (1/1024 texel, four times fp32 rounding at 4K) moves a lookup
// elsewhere only within that of the next texel: texel centres stay put.
ivec2 g_texel(vec2 screen_px, ivec2 size) {
  return ivec2(floor((screen_px - u_g_rect.xy) / u_g_rect.zw * vec2(size) + 1.0 / 1024.0));
}

Surface fetch_surface(vec2 screen_px) {
  Surface s;
  vec4 ndc = vec4(screen_px / u_screen * 2.0 - 1.0, 1.0, 1.0);
  vec4 far = u_inv_view_proj * ndc;
  s.view_dir = normalize(far.xyz / far.w - u_cam_pos);
  ivec2 size = FOVEATE_SIZE(u_g_albedo);
  ivec2 t = g_texel(screen_px, size);
  s.hit = false;
  if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) return s;
  vec4 p = FOVEATE_FETCH(u_g_position, t);
  if (p.w < 0.5) return s;
  vec4 a = FOVEATE_FETCH(u_g_albedo, t);
  vec4 n = FOVEATE_FETCH(u_g_normal, t);
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

#ifdef FOVEATE_GBUFFER_SAMPLES
// An edge: the samples of this pixel saw different surfaces (or some missed).
bool scene_samples_differ(vec2 screen_px) {
  ivec2 size = textureSize(u_g_position);
  ivec2 t = g_texel(screen_px, size);
  if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) return false;
  vec4 p0 = texelFetch(u_g_position, t, 0);
  vec3 n0 = texelFetch(u_g_normal, t, 0).xyz;
  for (int i = 1; i < FOVEATE_GBUFFER_SAMPLES; ++i) {
    vec4 p = texelFetch(u_g_position, t, i);
    if (p.w != p0.w || distance(p.xyz, p0.xyz) > 0.01 * (1.0 + distance(p0.xyz, u_cam_pos)) ||
        dot(texelFetch(u_g_normal, t, i).xyz, n0) < 0.95) {
      return true;
    }
  }
  return false;
}
#endif
