#include "output_dir.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"

namespace foveate::app {

OutputDirLock::OutputDirLock(const std::string& dir, const std::string& flag) {
  make_output_dir(dir, flag);
  const std::string name = flag + " " + dir;
  const std::string path = (std::filesystem::path(dir) / ".foveate.lock").string();
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd_ < 0) throw Error(name + ": cannot write into the folder: " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    std::string holder;
    char buf[32] = {};
    const ssize_t n = ::pread(fd_, buf, sizeof buf - 1, 0);
    if (n > 0) holder = std::string(buf, static_cast<size_t>(n));
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK) {
      throw Error(name + ": the folder is in use by another foveate run" +
                  (holder.empty() ? std::string() : " (pid " + holder + ")") +
                  "; wait for it to finish or choose another folder");
    }
    throw Error(name + ": cannot lock the folder: " + std::strerror(err));
  }
  // Who holds it, for the message another run prints.
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) == 0) {
    [[maybe_unused]] const ssize_t w = ::pwrite(fd_, pid.data(), pid.size(), 0);
  }
}

OutputDirLock::~OutputDirLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace foveate::app
