#include "foveate/core/file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "foveate/core/error.hpp"

namespace foveate {

namespace {

/// What a file that is not a regular file is, for messages.
const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a named pipe (FIFO)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string not_regular(const std::string& path, const std::string& what, mode_t mode) {
  return path + ": the " + what + " is " + kind_of(mode) + ", not a regular file";
}

std::string mib(std::uint64_t bytes) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return buf;
}

struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

void require_regular_file(const std::string& path, const std::string& what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    throw Error(path + ": cannot open the " + what + ": " + std::strerror(errno));
  }
  if (!S_ISREG(st.st_mode)) throw Error(not_regular(path, what, st.st_mode));
}

std::string read_file(const std::string& path, const std::string& what, std::uint64_t max_bytes,
                      const std::string& how_to_raise) {
  // Refused before the open where possible; the open itself does not block
  // (O_NONBLOCK), and the opened file is checked again (it may have changed).
  require_regular_file(path, what);
  Fd f;
  f.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (f.fd < 0) throw Error(path + ": cannot open the " + what + ": " + std::strerror(errno));
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) throw Error(path + ": cannot read: " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw Error(not_regular(path, what, st.st_mode));
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size > max_bytes) {
    throw Error(path + ": the " + what + " is " + mib(size) + ", over the limit of " +
                mib(max_bytes) + (how_to_raise.empty() ? "" : " (" + how_to_raise + ")"));
  }
  const int flags = ::fcntl(f.fd, F_GETFL);
  if (flags >= 0) ::fcntl(f.fd, F_SETFL, flags & ~O_NONBLOCK);
  std::string out;
  out.reserve(static_cast<size_t>(size));
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(f.fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error(path + ": read error: " + std::strerror(errno));
    if (n == 0) break;
    out.append(buf, static_cast<size_t>(n));
    if (out.size() > max_bytes) {  // grew while being read
      throw Error(path + ": the " + what + " grew past the limit of " + mib(max_bytes) +
                  " while being read" + (how_to_raise.empty() ? "" : " (" + how_to_raise + ")"));
    }
  }
  return out;
}

std::uint64_t limit_from_env_mib(const char* name, std::uint64_t fallback_mib) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback_mib * 1024 * 1024;
  char* end = nullptr;
  errno = 0;
  const unsigned long long x = std::strtoull(v, &end, 10);
  if (*end != '\0' || errno != 0 || x < 1 || x > (1ull << 30) || v[0] == '-') {
    throw Error(std::string(name) + ": expected a size in MiB (1.." + std::to_string(1ull << 30) +
                "), got '" + v + "'");
  }
  return static_cast<std::uint64_t>(x) * 1024 * 1024;
}

void write_file_atomic(const std::string& path, std::string_view contents) {
  namespace fs = std::filesystem;
  fs::path target(path);
  std::error_code probe;
  if (fs::is_directory(target, probe)) throw Error(path + ": is a directory; give a file name");
  fs::path tmp = target;
  tmp += ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.flush();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw Error(path + ": write failed (disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    const std::string why = ec.message();  // before the clean-up resets it
    fs::remove(tmp, ec);
    throw Error(path + ": cannot move the finished file into place: " + why);
  }
}

void make_output_dir(const std::string& dir, const std::string& option) {
  namespace fs = std::filesystem;
  const std::string name = option + " " + dir;
  if (dir.empty()) throw Error(option + ": give a folder");
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) throw Error(name + ": exists and is not a folder");
    return;
  }
  // A new folder named like a file is almost always a mistaken output
  // folder (frames and reports go inside it, as frame-0000.png, results.json, ...).
  std::string ext = fs::path(dir).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  for (const char* file : {".png", ".jpg", ".jpeg", ".mp4", ".mkv", ".webm", ".json", ".csv", ".md",
                           ".html", ".txt"}) {
    if (ext == file) {
      throw Error(name + ": names a file (" + ext + "), but " + option +
                  " is the folder the outputs are written into; give a folder, e.g. " + option +
                  " " + fs::path(dir).replace_extension().string());
    }
  }
  fs::create_directories(dir, ec);
  if (ec) throw Error(name + ": cannot create the folder: " + ec.message());
}

std::vector<std::string> run_outputs_in(const std::string& dir) {
  namespace fs = std::filesystem;
  static const char* const kNamed[] = {"results.json", "results.csv", "results.md", "report.html",
                                       "tune.json",    "tune.md",     "params.json"};
  const auto numbered = [](const std::string& name, const std::string& prefix) {
    if (name.size() <= prefix.size() + 4 || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - 4, 4, ".png") != 0)
      return false;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - 4);
    return digits.find_first_not_of("0123456789") == std::string::npos;
  };
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const std::string name = it->path().filename().string();
    bool ours = numbered(name, "frame-") || numbered(name, "reference-");
    for (const char* n : kNamed) ours = ours || name == n;
    if (ours) out.push_back(it->path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace foveate
