#pragma once
// The output folder of a run (render --out, bench --out, demo --out, tune
// --out, merge --out): created with errors that name it (an existing file, a
// read-only mount, /proc), locked for the run so that two runs never write
// into one folder at once, and refused when it holds an earlier run's output
// unless the run replaces it (--overwrite), so that no folder ever holds a
// mix of two runs' files.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

namespace foveate::app {

/// --overwrite on `sub`: replace an earlier run's output in --out.
void add_overwrite_flag(CLI::App* sub, bool& overwrite);

/// make_output_dir (foveate/core/file.hpp), then an exclusive lock (flock) on
/// DIR/.foveate.lock, held until destruction or the end of the process (the
/// kernel releases it even when the process is killed); the lock file is
/// removed on destruction. A second run on the same folder gets an error
/// naming the folder and the run that holds it. A folder holding the output
/// of an earlier run (run_outputs_in) is an error naming `flag` and
/// `overwrite_flag`, unless `overwrite`: then those files are removed first,
/// and a note says how many. The folders it had to create (the folder and
/// any parents that did not exist) are removed again on destruction if they
/// are still empty: a run that fails before writing leaves nothing behind.
class OutputDirLock {
 public:
  OutputDirLock(const std::string& dir, const std::string& flag, bool overwrite,
                const std::string& overwrite_flag = "--overwrite");
  ~OutputDirLock();
  OutputDirLock(const OutputDirLock&) = delete;
  OutputDirLock& operator=(const OutputDirLock&) = delete;
  /// What destruction does (idempotent): the lock file removed and the
  /// lock released, the folders it created removed if still empty.
  void end();

 private:
  void enlist();
  void lock(const std::string& name);
  void release();
  std::string path_;
  std::vector<std::filesystem::path> created_;  // innermost first
  int fd_ = -1;
};

/// Ends every folder this process holds (OutputDirLock::end) now: for a
/// process that must exit without unwinding (a frame stuck in the GL), so
/// that it leaves no lock file and no empty folder behind.
void end_output_dirs_now();

}  // namespace foveate::app
