#pragma once
// The output folder of a run (render --out, bench --out, demo --out): created
// with errors that name it (an existing file, a read-only mount, /proc), and
// locked for the run so that two runs never mix their frames in one folder.
#include <string>

namespace foveate::app {

/// make_output_dir (foveate/core/file.hpp), then an exclusive lock (flock) on DIR/.foveate.lock,
/// held until destruction or the end of the process (the kernel releases it even when the process
/// is killed). A second run on the same folder gets an error naming the folder and the run that
/// holds it. The lock file stays.
class OutputDirLock {
 public:
  OutputDirLock(const std::string& dir, const std::string& flag);
  ~OutputDirLock();
  OutputDirLock(const OutputDirLock&) = delete;
  OutputDirLock& operator=(const OutputDirLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace foveate::app
