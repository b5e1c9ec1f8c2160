// A tile with no finer neighbour: its class read bilinearly at the pixel's
// position (linear light: the sRGB target decodes on read). Drawn over those
// tiles only; the tiles next to a finer class run reconstruct.frag.
uniform sampler2D u_src;
uniform vec2 u_extent;  // the class target's size in screen pixels (texels x rate)
uniform vec2 u_shift;   // (rate - 1) / 2: texel i's sample is at pixel centre i * rate + 0.5
out vec4 o_color;
void main() { o_color = vec4(texture(u_src, (gl_FragCoord.xy + u_shift) / u_extent).rgb, 1.0); }
