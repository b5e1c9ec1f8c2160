// The checkerboard pattern (CheckerboardPattern in core/models.hpp), on
// top-left pixel coordinates. Quad index in the 2x2 tile: x-column * 2 + y-row;
// region k drops quads 1..k. A tile's region is decided by the distance from
// the gaze to the tile's nearest point, so region 0 holds the whole disc of
// radius u_thresholds.x and no tile is split.
uniform int u_block;
uniform vec2 u_gaze_top_left;  // pixels, origin top-left
uniform vec3 u_thresholds;  // region boundaries in pixels
uniform float u_height;

vec2 pattern_top_left(vec2 frag_gl) { return vec2(frag_gl.x, u_height - frag_gl.y); }

int pattern_region(vec2 frag_gl) {
  vec2 p = pattern_top_left(frag_gl);
  float s = 2.0 * float(u_block);
  vec2 tile = floor(p / s) * s;
  float d = distance(u_gaze_top_left, clamp(u_gaze_top_left, tile, tile + s));
  return d > u_thresholds.z ? 3 : d > u_thresholds.y ? 2 : d > u_thresholds.x ? 1 : 0;
}

bool pattern_kept(vec2 frag_gl) {
  vec2 p = pattern_top_left(frag_gl);
  float s = 2.0 * float(u_block);
  vec2 tile = floor(p / s) * s;
  int region = pattern_region(frag_gl);
  vec2 m = p - tile;
  int quad = (m.x >= float(u_block) ? 2 : 0) + (m.y >= float(u_block) ? 1 : 0);
  return quad == 0 || quad > region;
}
