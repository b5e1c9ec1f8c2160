#pragma once
// File helpers: whole-file reads with clear errors, and atomic writes (a
// temporary file in the same directory, then rename) so that no output is
// ever left half-written.
#include <string>
#include <string_view>

namespace foveate {

std::string read_file(const std::string& path);
void write_file_atomic(const std::string& path, std::string_view contents);

}  // namespace foveate
