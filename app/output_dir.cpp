#include "output_dir.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <vector>

#include "cli_util.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"

namespace foveate::app {

namespace {

// The pid written into a lock file by the run holding it (empty if none).
std::string holder_of(int fd) {
  std::string holder;
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  if (n > 0) holder = std::string(buf, static_cast<size_t>(n));
  while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
  return holder;
}

// The folders locked by this process, for end_output_dirs_now.
std::mutex& live_mutex() {
  static std::mutex m;
  return m;
}
std::vector<OutputDirLock*>& live() {
  static std::vector<OutputDirLock*> v;
  return v;
}

}  // namespace

void end_output_dirs_now() {
  const std::lock_guard<std::mutex> hold(live_mutex());
  for (OutputDirLock* d : live()) d->end();
}

void add_overwrite_flag(CLI::App* sub, bool& overwrite) {
  sub->add_flag("--overwrite", overwrite,
                "Replace the output of an earlier run in --out (its frames and reports are "
                "removed first); without it such a folder is refused, so that no folder holds "
                "a mix of two runs' files");
}

OutputDirLock::OutputDirLock(const std::string& dir, const std::string& flag, bool overwrite,
                             const std::string& overwrite_flag) {
  // The folders make_output_dir is about to create, innermost first.
  std::error_code probe;
  std::filesystem::path p = std::filesystem::absolute(dir, probe).lexically_normal();
  if (!probe && p.filename().empty()) p = p.parent_path();  // a trailing separator
  while (!probe && p.has_filename()) {
    const bool there = std::filesystem::exists(p, probe);
    if (probe || there) break;
    created_.push_back(p);
    p = p.parent_path();
  }
  make_output_dir(dir, flag);
  const std::string name = flag + " " + dir;
  path_ = (std::filesystem::path(dir) / ".foveate.lock").string();
  lock(name);
  const std::vector<std::string> earlier = run_outputs_in(dir);
  if (earlier.empty()) {
    enlist();
    return;
  }
  const std::string which =
      std::filesystem::path(earlier.front()).filename().string() +
      (earlier.size() > 1 ? " and " + std::to_string(earlier.size() - 1) + " more" : "");
  if (!overwrite) {
    release();
    throw Error(name + ": holds the output of an earlier run (" + which + "); pass " +
                overwrite_flag +
                " to replace it (its files are removed first) or choose another folder");
  }
  for (const std::string& f : earlier) {
    std::error_code ec;
    std::filesystem::remove(f, ec);
    if (ec) {
      release();
      throw Error(f + ": cannot remove the earlier run's file (" + overwrite_flag +
                  "): " + ec.message());
    }
  }
  if (!quiet()) {
    std::fprintf(stderr, "foveate: note: %s: removed the earlier run's output (%s), %s\n",
                 name.c_str(), which.c_str(), overwrite_flag.c_str());
  }
  enlist();
}

void OutputDirLock::enlist() {
  const std::lock_guard<std::mutex> hold(live_mutex());
  live().push_back(this);
}

void OutputDirLock::lock(const std::string& name) {
  // The run before may remove the lock file as it ends: a lock taken on a
  // file no longer at the path is no lock, so take it again on the new one.
  for (;;) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0) throw Error(name + ": cannot write into the folder: " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      const std::string holder = holder_of(fd_);
      ::close(fd_);
      fd_ = -1;
      if (err == EWOULDBLOCK) {
        throw Error(name + ": the folder is in use by another foveate run" +
                    (holder.empty() ? std::string() : " (pid " + holder + ")") +
                    "; wait for it to finish or choose another folder");
      }
      throw Error(name + ": cannot lock the folder: " + std::strerror(err));
    }
    struct stat held {
    }, now{};
    if (::fstat(fd_, &held) == 0 && ::stat(path_.c_str(), &now) == 0 && held.st_ino == now.st_ino &&
        held.st_dev == now.st_dev)
      break;
    ::close(fd_);
  }
  // Who holds it, for the message another run prints.
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) == 0) {
    [[maybe_unused]] const ssize_t w = ::pwrite(fd_, pid.data(), pid.size(), 0);
  }
}

void OutputDirLock::release() {
  if (fd_ < 0) return;
  // Removed while still held, so that no other run locks it in between.
  ::unlink(path_.c_str());
  ::close(fd_);  // closing releases the lock
  fd_ = -1;
}

void OutputDirLock::end() {
  release();
  // A folder this run made and left empty (it failed before writing): gone
  // again, innermost first; remove() leaves a folder that holds anything.
  for (const std::filesystem::path& p : created_) {
    std::error_code ec;
    if (!std::filesystem::is_empty(p, ec) || ec || !std::filesystem::remove(p, ec)) break;
  }
  created_.clear();
}

OutputDirLock::~OutputDirLock() {
  {
    const std::lock_guard<std::mutex> hold(live_mutex());
    auto& v = live();
    v.erase(std::remove(v.begin(), v.end(), this), v.end());
  }
  end();
}

}  // namespace foveate::app
