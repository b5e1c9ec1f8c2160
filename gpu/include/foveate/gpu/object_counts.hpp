#pragma once
// How many GL objects the gpu/ wrappers have made since the process started,
// per type: what a test reads to see that a technique keeps its storage
// from frame to frame (live_gl_objects in gl.hpp counts those alive now).
#include "foveate/gpu/gl.hpp"

namespace foveate::gpu {

GlObjectCounts gl_objects_created();

}  // namespace foveate::gpu
