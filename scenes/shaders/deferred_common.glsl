// Reading the mesh scenes' G-buffer at a screen position, and the camera ray.
#include "octahedral.glsl"
#ifdef FOVEATE_GBUFFER_SAMPLES
// Multisampled G-buffer (View::samples > 1): the shading main picks the sample.
uniform usampler2DMS u_g_surface;
int foveate_sample = 0;
#define FOVEATE_FETCH(tex, t) texelFetch(tex, t, foveate_sample)
#define FOVEATE_SIZE(tex) textureSize(tex)
#else
uniform usampler2D u_g_surface;
#define FOVEATE_FETCH(tex, t) texelFetch(tex, t, 0)
#define FOVEATE_SIZE(tex) textureSize(tex, 0)
#endif
uniform vec4 u_g_rect;        // the prepass view: x0, y0, w, h in screen pixels
uniform vec2 u_screen;
uniform mat4 u_inv_view_proj; // of the full frame
uniform vec3 u_cam_pos;
uniform float u_time;

// The camera ray through a screen position (full-frame pixels).
vec3 camera_ray(vec2 screen_px) {
  vec4 far = u_inv_view_proj * vec4(screen_px / u_screen * 2.0 - 1.0, 1.0, 1.0);
  return normalize(far.xyz / far.w - u_cam_pos);
}

// The G-buffer's packing is gbuffer.frag's. The position is the eye plus
// the ray through the texel's centre, whose screen position follows from
// the texel and the prepass view (jitter included), times the distance
// stored. Multisampled, every sample of a fragment holds what the fragment
// shader computed once at the pixel's centre (no per-sample shading), so
// the centre's ray is each sample's too.
bool g_covered(uvec4 g) { return unpackHalf2x16(g.w).y > 0.5; }
vec3 g_position(uvec4 g, ivec2 t, ivec2 size) {
  vec2 px = u_g_rect.xy + (vec2(t) + 0.5) * u_g_rect.zw / vec2(size);
  return u_cam_pos + camera_ray(px) * uintBitsToFloat(g.x);
}
vec3 g_normal(uvec4 g) { return octahedral_decode(unpackSnorm2x16(g.z)); }

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
  s.view_dir = camera_ray(screen_px);
  ivec2 size = FOVEATE_SIZE(u_g_surface);
  ivec2 t = g_texel(screen_px, size);
  s.hit = false;
  if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) return s;
  uvec4 g = FOVEATE_FETCH(u_g_surface, t);
  if (!g_covered(g)) return s;
  vec4 a = unpackUnorm4x8(g.y);
  s.hit = true;
  s.albedo = a.rgb;
  s.material = floor(a.a * 255.0 + 0.5);
  s.normal = g_normal(g);
  s.gloss = unpackHalf2x16(g.w).x;
  s.position = g_position(g, t, size);
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
  ivec2 size = textureSize(u_g_surface);
  ivec2 t = g_texel(screen_px, size);
  if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) return false;
  uvec4 g0 = texelFetch(u_g_surface, t, 0);
  vec3 p0 = g_position(g0, t, size);
  vec3 n0 = g_normal(g0);
  for (int i = 1; i < FOVEATE_GBUFFER_SAMPLES; ++i) {
    uvec4 g = texelFetch(u_g_surface, t, i);
    if (g_covered(g) != g_covered(g0) ||
        distance(g_position(g, t, size), p0) >
            0.01 * (1.0 + distance(p0, u_cam_pos)) ||
        dot(g_normal(g), n0) < 0.95) {
      return true;
    }
  }
  return false;
}
#endif
