// The composite with layers shown stale reprojected through their world points.
#define FOVEATE_WARP
#include "layered/composite_common.glsl"
