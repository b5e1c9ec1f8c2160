// Materials filtered by the spacing of the samples that shade them. A scene
// that includes this declares that it does: the shading passes (PassKit's
// mains) then set foveate_footprint_px, before each scene_shade, to how far
// apart on the screen, in pixels, their samples lie there (1 at native
// sampling, about 2 in a half-resolution layer, more in a foveated
// periphery; a supersampled reference's pixels are its own). Detail finer
// than that spacing cannot be sampled, only aliased into coarser patterns
// that the eye then sees; a material averages it away instead, as a
// texture's mipmaps do. Anything else that compiles the scene's shading
// leaves it at one pixel.
#define FOVEATE_FOOTPRINT 1
float foveate_footprint_px = 1.0;

// A square wave of period 2 (+1 on even cells, -1 on odd) box-filtered over
// `w` cells, per axis: the slopes of its integral, a triangle wave.
vec2 filtered_square(vec2 x, float w) {
  w = max(w, 1e-4);
  vec2 a = abs(fract((x - 0.5 * w) * 0.5) - 0.5), b = abs(fract((x + 0.5 * w) * 0.5) - 0.5);
  return 2.0 * (a - b) / w;
}
