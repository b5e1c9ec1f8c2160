// Temporal antialiasing of the log-polar buffer (temporal_common.glsl) for
// content without depth: the point is taken to have stayed where it was on
// the screen; only the gaze (the mapping) moved.
#include "logpolar/temporal_common.glsl"
void main() { o_color = lp_temporal(lp_texel_screen(), true); }
