#pragma once
// File helpers: whole-file reads with clear errors, and atomic writes (a
// temporary file in the same directory, then rename) so that no output is
// ever left half-written.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace foveate {

/// Throws foveate::Error naming `path` and `what` ("gaze trace", "display
/// JSON", ...) unless `path` is a regular file (symbolic links followed):
/// named pipes, devices, sockets and directories are refused before anything
/// opens them, so nothing blocks on a FIFO or reads a device forever.
void require_regular_file(const std::string& path, const std::string& what);

/// The whole file. Only regular files are read (checked on the opened file,
/// which is opened without blocking, so a FIFO cannot hang the open). A file
/// over `max_bytes` is refused with an error naming the limit and
/// `how_to_raise` (e.g. "set FOVEATE_MAX_TRACE_MB") before it is read.
std::string read_file(const std::string& path, const std::string& what = "file",
                      std::uint64_t max_bytes = UINT64_MAX, const std::string& how_to_raise = {});
void write_file_atomic(const std::string& path, std::string_view contents);

/// Creates the output folder `dir` and its parents. A foveate::Error names
/// `option` (what gave the folder: "--out", "out"), the folder and the
/// reason: an existing file, a name that looks like a file's (frames and
/// reports go inside the folder), a read-only mount.
void make_output_dir(const std::string& dir, const std::string& option);

/// The files in the folder `dir` that a foveate run writes there (render's
/// frame-NNNN.png and reference-NNNN.png; results.json, .csv, .md,
/// report.html, tune.json, tune.md and params.json of bench, demo, merge and
/// tune), as paths, sorted; empty when there are none or `dir` is no folder.
std::vector<std::string> run_outputs_in(const std::string& dir);

/// A limit in MiB from the environment variable `name` (a positive integer),
/// or `fallback_mib` when it is unset; a bad value is an error naming it.
std::uint64_t limit_from_env_mib(const char* name, std::uint64_t fallback_mib);

}  // namespace foveate
