// Mapping of a rectangular target onto a screen rectangle (native rendering,
// layers, insets): target pixel centres land on the rectangle's sample grid.
uniform vec4 u_map_rect;    // x0, y0, width, height in screen pixels (origin bottom-left)
uniform vec2 u_map_target;  // target size in pixels
// (zw / target is exactly 1 when the target has the rectangle's size: native
// pixel centres are then reproduced bit for bit.)
vec2 foveate_map(vec2 frag) { return u_map_rect.xy + frag * (u_map_rect.zw / u_map_target); }
