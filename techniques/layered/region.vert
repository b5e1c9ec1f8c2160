// Covers one region of the composite at depth u_depth (NDC): the polygon
// circumscribing the disc of radius u_radius (pixels) around u_centre, or the
// whole viewport when u_radius <= 0. Drawn innermost first with a depth test,
// each region's pixels run a composite that reads only the layers that can
// show there (llvmpipe pays for every texture fetch a shader makes).
uniform vec2 u_centre;
uniform float u_radius;
uniform vec2 u_viewport;
uniform float u_depth;
const int kSides = 48;  // the layered technique draws 3 * kSides vertices per disc
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
      px += u_radius / cos(kPi / float(kSides)) * vec2(cos(a), sin(a));
    }
    ndc = px / u_viewport * 2.0 - 1.0;
  }
  gl_Position = vec4(ndc, u_depth, 1.0);
}
