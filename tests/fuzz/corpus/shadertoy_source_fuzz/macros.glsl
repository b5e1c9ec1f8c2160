uniform vec3 iResolution;
uniform float iGlobalTime;
#define T(x) texture2D(iChannel1, x)
/* block
 comment */ void mainImage( out vec4 O, vec2 U ) {
  O = T(U / iResolution.xy) + textureCubeLod(iChannel2, vec3(1), 0.);
}
