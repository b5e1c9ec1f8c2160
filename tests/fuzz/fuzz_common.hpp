#pragma once
// What every fuzz target shares: the input as text, and the rule that a
// foveate::Error is the expected answer to bad input while anything else
// escapes to libFuzzer (which reports an uncaught exception as a crash).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "foveate/core/error.hpp"

namespace foveate::fuzz {

inline std::string text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Runs `f`; a foveate::Error is swallowed (a clear error is a correct answer).
template <typename F>
void expect_clean(F&& f) {
  try {
    f();
  } catch (const foveate::Error& e) {
    if (e.what()[0] == '\0') std::abort();  // an error must say what is wrong
  }
}

/// An invariant of a successful parse; a violation is a finding.
inline void check(bool ok) {
  if (!ok) std::abort();
}

}  // namespace foveate::fuzz
