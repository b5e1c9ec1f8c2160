#include "foveate/bench/environment.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <thread>

#include "foveate/core/error.hpp"
#include "foveate/core/format.hpp"
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

double seconds(const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); }

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

CpuSample sample_cpu() {
  CpuSample c;
  rusage self{};
  if (getrusage(RUSAGE_SELF, &self) == 0) c.own_s = seconds(self.ru_utime) + seconds(self.ru_stime);
  // The first line sums every CPU: user nice system idle iowait irq softirq
  // steal, in clock ticks (guest time is already inside user and nice).
  std::ifstream stat("/proc/stat");
  std::string cpu;
  double v[8] = {};
  const long hz = sysconf(_SC_CLK_TCK);
  if (!(stat >> cpu) || cpu != "cpu" || hz <= 0) return c;
  for (double& x : v) {
    if (!(stat >> x)) return c;
  }
  const double idle = v[3] + v[4];
  const double busy = v[0] + v[1] + v[2] + v[5] + v[6] + v[7];
  c.busy_s = busy / double(hz);
  c.total_s = (busy + idle) / double(hz);
  return c;
}

double others_cpu_share(const CpuSample& a, const CpuSample& b) {
  if (a.busy_s < 0 || b.busy_s < 0 || a.own_s < 0 || b.own_s < 0) return -1;
  // The kernel counts CPU time in ticks of 10 ms per CPU: over less than 4 s
  // of the machine's time (2 s on 2 cores) a few ticks either way would move
  // the share by several per cent, so it is not told.
  const double total = b.total_s - a.total_s;
  if (!(total >= 4.0)) return -1;
  const double others = (b.busy_s - a.busy_s) - (b.own_s - a.own_s);
  return std::clamp(others / total, 0.0, 1.0);
}

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
  e.cpu_start = sample_cpu();
  for (const char* name : kRunVariables) {
    if (const char* v = std::getenv(name)) e.variables[name] = v;
  }
  return e;
}

void finish_environment(RunEnvironment& env) {
  env.load_end = load_average();
  env.others_cpu_share = others_cpu_share(env.cpu_start, sample_cpu());
}

std::optional<std::string> busy_machine(const RunEnvironment& env) {
  if (env.others_cpu_share < kBusyCpuShare) return std::nullopt;
  return "other processes used " + format_percent(env.others_cpu_share, 2) +
         " of the CPU during this run (load average " + format_significant(env.load_start[0]) +
         " at its start, " + std::to_string(env.cores) +
         " hardware threads): frame times are inflated and noisier; speedups still compare "
         "within this run, but rerun on a quiet machine before quoting times";
}

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
