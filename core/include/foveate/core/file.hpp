#pragma once
// File helpers: whole-file reads with clear errors, and atomic writes (a
// temporary file in the same directory, then rename) so that no output is
// ever left half-written.
#include <string>
#include <string_view>

namespace foveate {

std::string read_file(const std::string& path);
/// Throws foveate::Error unless `path` names an existing regular file
/// (symbolic links followed): a directory, a named pipe (opening one blocks
/// until a writer comes), a device or a socket is refused before anything
/// opens it. `what` names the input in the message ("shader", "iChannel0
/// image"): "iChannel0 image 'x.png': is a named pipe (FIFO), not a regular file".
void require_regular_file(const std::string& path, std::string_view what);
void write_file_atomic(const std::string& path, std::string_view contents);

}  // namespace foveate
