#pragma once
// A parameter's value as the registry's messages write it.
#include <cstdio>
#include <string>

namespace foveate::detail {

inline std::string param_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

}  // namespace foveate::detail
