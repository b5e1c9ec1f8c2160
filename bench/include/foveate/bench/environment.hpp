#pragma once
// Where and how a benchmark ran, recorded in results.json so a figure can be
// traced to its machine, build and command: the command, foveate's version,
// the UTC date, the GL renderer, the CPU and the load around the run, and
// the environment variables that choose what runs.
#include <array>
#include <map>
#include <optional>
#include <string>

namespace foveate::bench {

/// CPU time, in seconds, of the whole machine (busy and in all) and of this
/// process (every thread: llvmpipe's rasterizers are threads of it); -1
/// where unknown.
struct CpuSample {
  double busy_s = -1, total_s = -1, own_s = -1;
};

/// The machine's and this process's CPU time now (/proc/stat, getrusage).
CpuSample sample_cpu();
/// The share (0..1) of the machine's CPU time between `a` and `b` that went
/// to other processes (or to the hypervisor: steal); -1 where unknown or
/// where the interval is under 4 s of the machine's CPU time (2 s on 2
/// cores), too short for the kernel's ticks to tell.
double others_cpu_share(const CpuSample& a, const CpuSample& b);

struct RunEnvironment {
  std::string command;     ///< what started the run (the full command line)
  std::string version;     ///< foveate's version
  std::string date_utc;    ///< ISO 8601, when the run started
  std::string renderer;    ///< GL_RENDERER
  std::string gl_version;  ///< GL_VERSION
  std::string cpu_model;   ///< /proc/cpuinfo's model name (empty when unknown)
  unsigned cores = 0;      ///< hardware threads
  std::array<double, 3> load_start{}, load_end{};  ///< 1, 5 and 15 minute load averages
  /// Share of the machine's CPU time that other processes used during the
  /// run (others_cpu_share); -1 where unknown.
  double others_cpu_share = -1;
  /// Whether every measured frame (and the last warm-up frame) ran pass by
  /// pass, glFinish around each pass: on a renderer without GPU timers
  /// (llvmpipe), where a pipelined frame's time depends on the technique
  /// rendered before it (docs/performance.md).
  bool pass_by_pass = false;
  /// Whether the measured frames were timed in a pass that read nothing back,
  /// and rendered again from the start to be judged or encoded: so wherever
  /// every frame is read back (image metrics, video). Otherwise the last
  /// frame's images are read back between its timed renders.
  bool timed_apart = false;
  CpuSample cpu_start;  ///< what capture_environment sampled, for finish_environment
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
/// Records the load average at the end of the run and the share of the CPU
/// that other processes used since capture_environment.
void finish_environment(RunEnvironment& env);
/// The share of the CPU taken by other work from which a run's times are
/// called inflated (busy_machine).
inline constexpr double kBusyCpuShare = 0.2;
/// Where other work took kBusyCpuShare or more of the machine's CPU time during
/// the run, what to tell the user: it inflates frame times (four to six
/// times with twelve busy processes on 2 cores under llvmpipe,
/// docs/performance.md) and their noise. Ratios within the run still
/// compare; absolute times do not. Nothing when the share is unknown.
std::optional<std::string> busy_machine(const RunEnvironment& env);
/// Throws an Error naming `name` unless `env` is of the same foveate and the
/// same kRunVariables as `first` (named `first_name`): shards of one run.
void check_same_build(const RunEnvironment& env, const std::string& name,
                      const RunEnvironment& first, const std::string& first_name);

}  // namespace foveate::bench
