// Covers one region of a full-screen pass at depth u_depth (NDC): a polygon
// around the disc of radius u_radius (pixels) at u_centre, circumscribing it
// (u_inscribed = 0: covers every pixel of the disc) or inscribed in it
// (u_inscribed = 1: covers only pixels of the disc), or the whole viewport
// when u_radius <= 0. See foveate/techniques/depth_regions.hpp.
uniform vec2 u_centre;
uniform float u_radius;
uniform int u_inscribed;
uniform vec2 u_viewport;
uniform float u_depth;
const int kSides = 48;  // DepthRegions draws 3 * kSides vertices per disc
const float kPi = 3.14159265358979;
void main() {
  vec2 ndc;
  if (u_radius <= 0.0) {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    ndc = p * 2.0 - 1.0;
  } else {
    int tri = gl_VertexID / 3, corner = gl_VertexID % 3;
    vec2 px = u_centre;
    if (corner != 0) {
      float a = 2.0 * kPi * float(tri + corner - 1) / float(kSides);
      float reach = u_inscribed != 0 ? u_radius : u_radius / cos(kPi / float(kSides));
      px += reach * vec2(cos(a), sin(a));
    }
    ndc = px / u_viewport * 2.0 - 1.0;
  }
  gl_Position = vec4(ndc, u_depth, 1.0);
}
