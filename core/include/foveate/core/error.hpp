#pragma once
// One error type for everything the user can get wrong: bad files, bad
// configuration values, bad command-line values. The message says what and
// where ("display.width_mm: must be > 0, got -3").
#include <stdexcept>
#include <string>

namespace foveate {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace foveate
