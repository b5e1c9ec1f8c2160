// foveate gaze: statistics of gaze recordings (I-VT), recording from a live
// Pupil Capture, and synthetic traces from the seeded viewer model.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "cli_util.hpp"
#include "commands.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/gaze/analysis.hpp"
#include "foveate/gaze/pupil.hpp"
#include "foveate/gaze/synthetic.hpp"
#include "foveate/gaze/trace.hpp"

namespace foveate::app {

namespace {

using namespace foveate::gaze;

Display display_from(const std::string& name, const std::string& size) {
  Display d = Display::load(name);
  if (!size.empty()) {
    const PixelSize s = parse_size(size, "--size");
    d = d.resized(s.width, s.height);
  }
  return d;
}

TimeUnit time_unit_from(const std::string& s) {
  if (s.empty()) return TimeUnit::kAuto;
  if (s == "s") return TimeUnit::kSeconds;
  if (s == "ms") return TimeUnit::kMilliseconds;
  throw Error("--time-unit: expected s or ms, got '" + s + "'");
}

PosUnit pos_unit_from(const std::string& s) {
  if (s.empty()) return PosUnit::kAuto;
  if (s == "normalized") return PosUnit::kNormalized;
  if (s == "px") return PosUnit::kPixels;
  throw Error("--units: expected normalized or px, got '" + s + "'");
}

// ------------------------------------------------------------ stats

struct StatsArgs {
  std::string file;
  std::string display = "desktop-1080p";
  std::string size;
  std::string time_unit;
  std::string units;
  double velocity = 100.0;
  double min_fixation_ms = 60.0;
  double min_confidence = 0.6;
  bool json = false;
  bool strict = false;
};

void run_stats(const StatsArgs& a) {
  const Display d = display_from(a.display, a.size);
  TraceOptions to;
  to.time_unit = time_unit_from(a.time_unit);
  to.pos_unit = pos_unit_from(a.units);
  to.width_px = d.width_px;
  to.height_px = d.height_px;
  to.strict = a.strict;
  if (!(a.velocity > 0 && a.velocity < 10000)) throw Error("--velocity: expected 0..10000 deg/s");
  if (!(a.min_fixation_ms >= 0 && a.min_fixation_ms < 10000))
    throw Error("--min-fixation: expected 0..10000 ms");
  if (!(a.min_confidence >= 0 && a.min_confidence <= 1))
    throw Error("--min-confidence: expected 0..1");
  const Trace trace = load_trace(a.file, to);
  for (const std::string& w : trace.warnings)
    std::fprintf(stderr, "foveate: warning: %s\n", w.c_str());
  IvtOptions io;
  io.velocity_deg_per_s = a.velocity;
  io.min_fixation_s = a.min_fixation_ms * 1e-3;
  io.min_confidence = a.min_confidence;
  const TraceStats st = analyze_trace(trace, d, io);
  double amp = 0, peak = 0;
  for (const Saccade& s : st.saccades) {
    amp += s.amplitude_deg;
    peak = std::max(peak, s.peak_deg_per_s);
  }
  const double mean_amp = st.saccades.empty() ? 0.0 : amp / static_cast<double>(st.saccades.size());

  if (a.json) {
    nlohmann::json j;
    j["file"] = a.file;
    j["format"] = trace.format;
    j["samples"] = st.samples;
    j["duration_s"] = st.duration_s;
    j["rate_hz"] = st.rate_hz;
    j["dropped"] = {{"non_finite", st.dropped.non_finite},
                    {"out_of_range", st.dropped.out_of_range},
                    {"backwards", st.dropped.backwards},
                    {"duplicate", st.dropped.duplicate},
                    {"total", st.dropped.total()}};
    j["skipped_rows"] = trace.skipped_rows;
    j["lost_samples"] = st.lost_samples;
    j["dropouts"] = {
        {"count", st.dropouts}, {"total_s", st.dropout_s}, {"longest_s", st.longest_dropout_s}};
    j["ivt"] = {{"velocity_deg_per_s", a.velocity},       {"saccades", st.saccades.size()},
                {"mean_saccade_amplitude_deg", mean_amp}, {"max_peak_velocity_deg_per_s", peak},
                {"fixations", st.fixations.size()},       {"mean_fixation_s", st.mean_fixation_s}};
    if (st.has_latency) {
      j["latency_ms"] = {
          {"median", st.latency_median_ms}, {"p95", st.latency_p95_ms}, {"max", st.latency_max_ms}};
    } else {
      j["latency_ms"] = nullptr;
    }
    std::cout << j.dump(2) << '\n';
    return;
  }
  std::printf("%s (%s): %zu samples over %.2f s, %.1f Hz\n", a.file.c_str(), trace.format.c_str(),
              st.samples, st.duration_s, st.rate_hz);
  std::printf("dropped while reading: %s\n", st.dropped.summary().c_str());
  if (trace.skipped_rows > 0) {
    std::printf("rows that could not be read (skipped): %llu\n",
                static_cast<unsigned long long>(trace.skipped_rows));
  }
  std::printf("lost samples (invalid or confidence < %.2f): %zu\n", a.min_confidence,
              st.lost_samples);
  std::printf("dropouts: %zu, %.3f s in total, longest %.0f ms\n", st.dropouts, st.dropout_s,
              st.longest_dropout_s * 1e3);
  std::printf(
      "I-VT at %.0f deg/s on %s: %zu saccades (mean amplitude %.1f deg, fastest %.0f deg/s), "
      "%zu fixations (mean %.0f ms)\n",
      a.velocity, d.name.c_str(), st.saccades.size(), mean_amp, peak, st.fixations.size(),
      st.mean_fixation_s * 1e3);
  if (st.has_latency) {
    std::printf("latency: median %.1f ms, p95 %.1f ms, max %.1f ms\n", st.latency_median_ms,
                st.latency_p95_ms, st.latency_max_ms);
  } else {
    std::printf("latency: not recorded in this file\n");
  }
}

// ------------------------------------------------------------ record

struct RecordArgs {
  std::string from;
  std::string out;
  double seconds = 10.0;
  double connect_timeout = 5.0;
};

// The signal that stopped the recording (0: none yet).
std::atomic<int> g_stop_signal{0};
extern "C" void on_stop_signal(int sig) { g_stop_signal.store(sig); }

/// SIGINT, SIGTERM and SIGHUP stop the recording the same way: what was
/// received so far is written (atomically) before the process ends. The
/// previous handlers come back when the recording is written or abandoned.
class StopSignals {
 public:
  StopSignals() {
    g_stop_signal.store(0);
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < 3; ++i) sigaction(kSignals[i], &sa, &previous_[i]);
  }
  ~StopSignals() {
    for (size_t i = 0; i < 3; ++i) sigaction(kSignals[i], &previous_[i], nullptr);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  [[nodiscard]] static int received() { return g_stop_signal.load(); }

 private:
  static constexpr int kSignals[3] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction previous_[3]{};
};

const char* signal_name(int sig) {
  switch (sig) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

void run_record(const RecordArgs& a) {
  if (a.from != "pupil" && a.from.rfind("pupil:", 0) != 0) {
    throw Error("--from: expected pupil or pupil:HOST:PORT, got '" + a.from + "'");
  }
  if (!(a.seconds > 0 && a.seconds <= 24 * 3600))
    throw Error("--seconds: expected more than 0 and at most 86400 (a day)");
  if (!(a.connect_timeout > 0 && a.connect_timeout <= 600))
    throw Error("--connect-timeout: expected more than 0 and at most 600 s");
  PupilOptions po = parse_pupil_address(a.from == "pupil" ? "" : a.from.substr(6));
  po.queue_limit = 1 << 20;
  PupilSource src(po);
  if (!src.wait_connected(a.connect_timeout)) {
    const std::string why = src.counters().last_failure;
    if (why.rfind("the answer", 0) == 0) {  // it answered, but not as Pupil Remote does
      throw Error("--from " + a.from + ": Pupil Capture at " + po.host + ":" +
                  std::to_string(po.port) + " answered, but " + why);
    }
    throw Error("cannot reach Pupil Capture at " + po.host + ":" + std::to_string(po.port) +
                " within " + format_fixed(a.connect_timeout, 1) + " s (is Pupil Remote enabled?)" +
                (why.empty() ? "" : ": " + why));
  }
  const StopSignals signals;
  if (!quiet())
    std::fprintf(stderr,
                 "recording %s for %.1f s (Ctrl-C, SIGTERM or SIGHUP stop early and keep what was "
                 "recorded)\n",
                 src.describe().c_str(), a.seconds);
  Trace trace;
  trace.format = "csv";
  std::vector<double> arrivals;
  const double start = src.now_s();
  auto collect = [&] {
    const std::vector<GazeSample> got = src.drain(&arrivals);
    for (size_t i = 0; i < got.size(); ++i) {
      trace.samples.push_back(got[i]);
      // Arrival minus capture, the capture time mapped to this clock by the
      // offset measured at the handshake: that estimate errs by microseconds,
      // so a sample delivered at once can come out a few us negative (seen:
      // -0.009 ms). No sample arrives before it was taken.
      trace.latency_ms.push_back(std::max(0.0, (arrivals[i] - got[i].time_s) * 1e3));
    }
  };
  while (StopSignals::received() == 0 && src.now_s() - start < a.seconds) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    collect();
  }
  collect();
  const PupilCounters c = src.counters();
  if (trace.samples.empty()) {
    throw Error("no gaze received from " + po.host + ":" + std::to_string(po.port) + " (" +
                c.summary() + ")");
  }
  trace.time_origin_s = trace.samples.front().time_s;
  for (GazeSample& s : trace.samples) s.time_s -= trace.time_origin_s;
  trace.dropped = c.dropped;
  write_file_atomic(a.out, trace_to_csv(trace));
  if (StopSignals::received() != 0) {
    std::fprintf(stderr, "stopped by %s\n", signal_name(StopSignals::received()));
  }
  std::printf("wrote %s: %zu samples over %.2f s; %s\n", a.out.c_str(), trace.samples.size(),
              trace.duration_s(), c.summary().c_str());
  std::fflush(stdout);
}

// ------------------------------------------------------------ synth

struct SynthArgs {
  long long seed = 1;
  double seconds = 10.0;
  double rate = 120.0;
  double noise = 0.0;
  std::string out;
  std::string display = "desktop-1080p";
  std::string size;
};

void run_synth(const SynthArgs& a) {
  const std::string ext = std::filesystem::path(a.out).extension().string();
  if (ext != ".csv" && ext != ".json")
    throw Error("--out: the file must end in .csv or .json, got '" + a.out + "'");
  if (!(a.seconds > 0 && a.seconds <= 24 * 3600))
    throw Error("--seconds: expected more than 0 and at most 86400 (a day)");
  if (!(a.rate >= 1 && a.rate <= 10000)) throw Error("--rate: expected 1..10000 Hz");
  if (!(a.noise >= 0 && a.noise <= 10)) throw Error("--noise: expected 0..10 degrees");
  if (a.seed < 0)
    throw Error("--seed: expected a non-negative integer, got " + std::to_string(a.seed));
  const Display d = display_from(a.display, a.size);
  SyntheticOptions o;
  o.seed = static_cast<std::uint64_t>(a.seed);
  o.noise_deg = a.noise;
  SyntheticViewer v(d, o);
  Trace t;
  const auto n = static_cast<long long>(a.seconds * a.rate);
  for (long long k = 0; k <= n; ++k) {
    const double time_s = static_cast<double>(k) / a.rate;
    GazeSample s = v.sample(time_s);
    s.time_s = time_s;
    t.samples.push_back(s);
  }
  const bool json = a.out.size() >= 5 && a.out.substr(a.out.size() - 5) == ".json";
  write_file_atomic(a.out, json ? trace_to_json(t) : trace_to_csv(t));
  int counts[5] = {0, 0, 0, 0, 0};
  for (const Movement& m : v.movements_until(a.seconds)) ++counts[static_cast<int>(m.kind)];
  std::printf(
      "wrote %s: %zu samples at %.0f Hz over %.1f s (seed %llu): %d fixations, %d saccades, "
      "%d pursuits, %d blinks, %d microsaccades\n",
      a.out.c_str(), t.samples.size(), a.rate, a.seconds, static_cast<unsigned long long>(a.seed),
      counts[0], counts[1], counts[2], counts[3], counts[4]);
}

}  // namespace

void register_gaze(CLI::App& app) {
  CLI::App* gaze = app.add_subcommand(
      "gaze", "Gaze recordings: statistics, recording from Pupil Capture, synthetic traces");
  gaze->require_subcommand(1);

  auto s = std::make_shared<StatsArgs>();
  CLI::App* stats = gaze->add_subcommand("stats",
                                         "Sample rate, dropouts, dropped samples by reason, "
                                         "saccades and fixations (I-VT) of a gaze file");
  stats
      ->add_option("FILE", s->file,
                   "CSV (time_s|time_ms, x|x_px, y|y_px[, confidence, valid, latency_ms]), Pupil's "
                   "gaze_positions.csv or JSON")
      ->required();
  stats->add_option("--display", s->display, "Display preset or JSON file, for degrees")
      ->capture_default_str();
  stats->add_option("--size", s->size,
                    "Screen size WxH the pixel positions refer to (default: the display's)");
  stats->add_option("--time-unit", s->time_unit,
                    "s or ms, when the header does not say (default s)");
  stats->add_option("--units", s->units,
                    "normalized or px, when the header does not say (default normalized)");
  stats->add_option("--velocity", s->velocity, "I-VT saccade threshold in deg/s")
      ->capture_default_str();
  stats->add_option("--min-fixation", s->min_fixation_ms, "Shortest fixation counted, ms")
      ->capture_default_str();
  stats->add_option("--min-confidence", s->min_confidence, "Samples below are lost")
      ->capture_default_str();
  stats->add_flag("--json", s->json, "Print JSON");
  stats->add_flag("--strict", s->strict,
                  "A row that cannot be read is an error (default: skipped with a warning naming "
                  "its line; a last line cut off mid-write likewise)");
  stats->callback([s] { run_stats(*s); });

  auto r = std::make_shared<RecordArgs>();
  CLI::App* record = gaze->add_subcommand(
      "record",
      "Record live gaze from Pupil Capture / Pupil Service (Pupil Remote) to a CSV trace");
  record->add_option("--from", r->from, "pupil or pupil:HOST:PORT (default port 50020)")
      ->required();
  record->add_option("--out", r->out, "Output CSV (written atomically when done)")->required();
  record->add_option("--seconds", r->seconds, "How long to record")->capture_default_str();
  record
      ->add_option("--connect-timeout", r->connect_timeout,
                   "Give up if the tracker does not answer, s")
      ->capture_default_str();
  record->callback([r] { run_record(*r); });

  auto y = std::make_shared<SynthArgs>();
  CLI::App* synth = gaze->add_subcommand(
      "synth",
      "Write a trace of the synthetic viewer (fixations, main-sequence saccades, pursuit, blinks)");
  synth->add_option("--seed", y->seed, "Seed; the same seed gives the same trace")
      ->capture_default_str();
  synth->add_option("--seconds", y->seconds, "Length")->capture_default_str();
  synth->add_option("--rate", y->rate, "Tracker sample rate, Hz")->capture_default_str();
  synth->add_option("--noise", y->noise, "Tracker noise, degrees (Gaussian per axis)")
      ->capture_default_str();
  synth->add_option("--display", y->display, "Display preset or JSON file (geometry for degrees)")
      ->capture_default_str();
  synth->add_option("--size", y->size, "Render size WxH with the display's field of view");
  synth->add_option("--out", y->out, "Output file: .csv or .json")->required();
  synth->callback([y] { run_synth(*y); });
}

const CommandRegistrar kGaze(60, register_gaze);

}  // namespace foveate::app
