// The checkerboard pattern (CheckerboardPattern in core/models.hpp), on
// top-left pixel coordinates. Quad index in the 2x2 tile: x-column * 2 + y-row;
// region k drops quads 1..k.
uniform int u_block;
uniform vec2 u_gaze_top_left;  // pixels, origin top-left
uniform vec3 u_thresholds;  // region boundaries in pixels
uniform float u_height;

int pattern_region(vec2 frag_gl) {
  vec2 p = vec2(frag_gl.x, u_height - frag_gl.y);
  float s = 2.0 * float(u_block);
  float d = distance(floor(p / s) * s, floor(u_gaze_top_left / s) * s);
  return d > u_thresholds.z ? 3 : d > u_thresholds.y ? 2 : d > u_thresholds.x ? 1 : 0;
}

bool pattern_kept(vec2 frag_gl) {
  vec2 p = vec2(frag_gl.x, u_height - frag_gl.y);
  float s = 2.0 * float(u_block);
  vec2 tile = floor(p / s) * s;
  int region = pattern_region(frag_gl);
  vec2 m = p - tile;
  int quad = (m.x >= float(u_block) ? 2 : 0) + (m.y >= float(u_block) ? 1 : 0);
  return quad == 0 || quad > region;
}
