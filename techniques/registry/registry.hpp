#pragma once
// The built-in techniques, one per folder. Adding one: a folder with its code
// and shaders (CMake picks it up) that defines `TechniqueInfo NAME_info()`,
// and its name in this list.
#include "foveate/techniques/technique.hpp"

#define FOVEATE_BUILTIN_TECHNIQUES(X) \
  X(native)                           \
  X(layered)                          \
  X(logpolar)                         \
  X(checkerboard)                     \
  X(lodmask)                          \
  X(inset)                            \
  X(vrs)                              \
  X(marwarp)

namespace foveate::tech {

#define FOVEATE_DECLARE_INFO(name) TechniqueInfo name##_info();
FOVEATE_BUILTIN_TECHNIQUES(FOVEATE_DECLARE_INFO)
#undef FOVEATE_DECLARE_INFO

}  // namespace foveate::tech
