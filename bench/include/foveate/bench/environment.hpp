#pragma once
// Where and how a benchmark ran, recorded in results.json so a figure can be
// traced to its machine, build and command: the command, foveate's version,
// the UTC date, the GL renderer, the CPU and the load around the run.
#include <array>
#include <string>

namespace foveate::bench {

struct RunEnvironment {
  std::string command;     ///< what started the run (the full command line)
  std::string version;     ///< foveate's version
  std::string date_utc;    ///< ISO 8601, when the run started
  std::string renderer;    ///< GL_RENDERER
  std::string gl_version;  ///< GL_VERSION
  std::string cpu_model;   ///< /proc/cpuinfo's model name (empty when unknown)
  unsigned cores = 0;      ///< hardware threads
  std::array<double, 3> load_start{}, load_end{};  ///< 1, 5 and 15 minute load averages
};

/// Captures everything but load_end (needs a current GL context).
RunEnvironment capture_environment(const std::string& command);
/// Records the load average at the end of the run.
void finish_environment(RunEnvironment& env);

}  // namespace foveate::bench
