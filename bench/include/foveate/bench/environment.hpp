#pragma once
// Where and how a benchmark ran, recorded in results.json so a figure can be
// traced to its machine, build and command: the command, foveate's version,
// the UTC date, the GL renderer, the CPU and the load around the run, and
// the environment variables that choose what runs.
#include <array>
#include <map>
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
  /// Those of kRunVariables that were set, by name: the same build on the
  /// same renderer runs other passes under them.
  std::map<std::string, std::string> variables;
};

/// Environment variables that choose what a run measures: the EGL platform
/// (FOVEATE_EGL) and how subsampled buffers' edges are reshaded
/// (FOVEATE_EDGES, PassKit::indirect_edges).
inline constexpr const char* kRunVariables[] = {"FOVEATE_EGL", "FOVEATE_EDGES"};

/// Captures everything but load_end (needs a current GL context).
RunEnvironment capture_environment(const std::string& command);
/// Records the load average at the end of the run.
void finish_environment(RunEnvironment& env);
/// Throws an Error naming `name` unless `env` is of the same foveate and the
/// same kRunVariables as `first` (named `first_name`): shards of one run.
void check_same_build(const RunEnvironment& env, const std::string& name,
                      const RunEnvironment& first, const std::string& first_name);

}  // namespace foveate::bench
