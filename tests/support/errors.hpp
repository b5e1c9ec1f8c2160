#pragma once
// The message of the foveate::Error a call throws, or "no error".
#include <functional>
#include <string>

#include "foveate/core/error.hpp"

namespace foveate::test {

inline std::string error_of(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace foveate::test
