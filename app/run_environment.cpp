#include "run_environment.hpp"

#include <cstdlib>
#include <ctime>
#include <fstream>
#include <thread>

#include "foveate/gpu/gl.hpp"

#ifndef FOVEATE_VERSION
#define FOVEATE_VERSION "unknown"
#endif

namespace foveate::app {

namespace {

std::string& invocation_storage() {
  static std::string s;
  return s;
}

// An argument as a POSIX shell would need it to read it back unchanged.
std::string shell_quote(const std::string& a) {
  if (!a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789-_./=:,+@%") == std::string::npos)
    return a;
  std::string q = "'";
  for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::array<double, 3> load_average() {
  std::array<double, 3> l{-1, -1, -1};
  if (getloadavg(l.data(), 3) != 3) l = {-1, -1, -1};
  return l;
}

std::string gl_string(GLenum name) {
  const auto* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

void set_invocation(int argc, const char* const* argv) {
  std::string s = "foveate";  // argv[0] is wherever the binary was
  for (int i = 1; i < argc; ++i) s += " " + shell_quote(argv[i]);
  invocation_storage() = s;
}

const std::string& invocation() { return invocation_storage(); }

RunEnvironment capture_environment(const std::string& command) {
  RunEnvironment e;
  e.command = command;
  e.version = FOVEATE_VERSION;
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  e.date_utc = buf;
  e.renderer = gl_string(GL_RENDERER);
  e.gl_version = gl_string(GL_VERSION);
  std::ifstream cpu("/proc/cpuinfo");
  for (std::string line; std::getline(cpu, line);) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos)
        e.cpu_model = line.substr(line.find_first_not_of(" \t", colon + 1));
      break;
    }
  }
  e.cores = std::thread::hardware_concurrency();
  e.load_start = load_average();
  return e;
}

void finish_environment(RunEnvironment& env) { env.load_end = load_average(); }

}  // namespace foveate::app
