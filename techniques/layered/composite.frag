// The composite of layers all rendered this frame (or without world points).
#include "layered/composite_common.glsl"
