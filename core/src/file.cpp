#include "foveate/core/file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "foveate/core/error.hpp"

namespace foveate {

std::string read_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open: " + std::strerror(errno));
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw Error(path + ": read error");
  return s.str();
}

void require_regular_file(const std::string& path, std::string_view what) {
  const std::string name = std::string(what) + " '" + path + "'";
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    throw Error(name + ": " + (errno == ENOENT ? "no such file" : std::strerror(errno)));
  }
  const char* kind = nullptr;
  if (S_ISDIR(st.st_mode))
    kind = "a directory";
  else if (S_ISFIFO(st.st_mode))
    kind = "a named pipe (FIFO)";
  else if (S_ISCHR(st.st_mode))
    kind = "a character device";
  else if (S_ISBLK(st.st_mode))
    kind = "a block device";
  else if (S_ISSOCK(st.st_mode))
    kind = "a socket";
  else if (!S_ISREG(st.st_mode))
    kind = "a special file";
  if (kind) throw Error(name + ": is " + std::string(kind) + ", not a regular file");
}

void write_file_atomic(const std::string& path, std::string_view contents) {
  namespace fs = std::filesystem;
  fs::path target(path);
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
    fs::remove(tmp, ec);
    throw Error(path + ": cannot move the finished file into place: " + ec.message());
  }
}

}  // namespace foveate
