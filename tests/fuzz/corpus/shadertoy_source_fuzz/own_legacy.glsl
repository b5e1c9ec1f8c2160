// A shader that defines legacy names itself: foveate adds nothing that
// would clash (a second texture2D macro, a textureCube of its own).
#define texture2D texture
uniform float iGlobalTime;
vec4 textureCube(sampler2D s, vec3 d) { return vec4(0.25, 0.5, 0.75, 1.0); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  // iGlobalTime declared here is set like iTime: at --time 1, 1.0.
  fragColor = textureCube(iChannel0, vec3(0.0)) * iGlobalTime + 0.0 * texture2D(iChannel0, vec2(0.5));
}
