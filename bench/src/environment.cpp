#include "foveate/bench/environment.hpp"

#include <cstdlib>
#include <ctime>
#include <fstream>
#include <thread>

#include "foveate/core/error.hpp"
#include "foveate/gpu/gl.hpp"

#ifndef FOVEATE_VERSION
#define FOVEATE_VERSION "unknown"
#endif

namespace foveate::bench {

namespace {

std::array<double, 3> load_average() {
  std::array<double, 3> l{-1, -1, -1};
  if (getloadavg(l.data(), 3) != 3) l = {-1, -1, -1};
  return l;
}

std::string gl_string(GLenum name) {
  const auto* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

std::string cpu_model() {
  std::ifstream cpu("/proc/cpuinfo");
  for (std::string line; std::getline(cpu, line);) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
      break;
    }
  }
  return {};
}

}  // namespace

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
  e.cpu_model = cpu_model();
  e.cores = std::thread::hardware_concurrency();
  e.load_start = load_average();
  for (const char* name : kRunVariables) {
    if (const char* v = std::getenv(name)) e.variables[name] = v;
  }
  return e;
}

void finish_environment(RunEnvironment& env) { env.load_end = load_average(); }

void check_same_build(const RunEnvironment& env, const std::string& name,
                      const RunEnvironment& first, const std::string& first_name) {
  if (env.version != first.version) {
    throw Error(name + ": foveate " + env.version + ", but " + first_name + " is from foveate " +
                first.version);
  }
  const auto shown = [](const std::map<std::string, std::string>& v) {
    std::string s;
    for (const auto& [k, x] : v) s += (s.empty() ? "" : " ") + k + "=" + x;
    return s.empty() ? std::string("none set") : s;
  };
  if (env.variables != first.variables) {
    throw Error(name + ": run with " + shown(env.variables) + ", but " + first_name + " with " +
                shown(first.variables) + " (environment variables that choose what runs)");
  }
}

}  // namespace foveate::bench
