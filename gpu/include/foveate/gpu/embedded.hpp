#pragma once
// A text file embedded in the binary at build time (see cmake/EmbedFiles.cmake).
#include <string_view>

namespace foveate::embedded {

struct EmbeddedFile {
  std::string_view name;  ///< path relative to its module, e.g. "techniques/layered/composite.frag"
  std::string_view text;
};

}  // namespace foveate::embedded
