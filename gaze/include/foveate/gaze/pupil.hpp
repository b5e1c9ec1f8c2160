#pragma once
// Live gaze from Pupil Labs Pupil Capture or Pupil Service over its network
// API (Pupil Remote):
//   * a REQ socket to the control port (50020 by default) asks "SUB_PORT" (the
//     reply is the port of the IPC backbone's publisher) and "t" (the reply is
//     the tracker's current clock in seconds, which gives the clock offset);
//   * a SUB socket on that port subscribes to "gaze."; each message is
//     multipart [topic, msgpack map] with norm_pos ([x, y], origin
//     bottom-left), confidence and timestamp (tracker clock, seconds).
// The receiver runs on a background thread. Every receive has a timeout; when
// the publisher stays silent for `silence_s`, it asks SUB_PORT again (the
// tracker may have restarted on a new port, with a new clock) and reconnects.
// Inbound frames are capped by ZMQ_MAXMSGSIZE and msgpack unpack limits, so a
// malformed or hostile frame cannot exhaust memory: it is counted and skipped.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "foveate/gaze/gaze.hpp"

namespace foveate::gaze {

struct PupilOptions {
  std::string host = "127.0.0.1";
  int port = 50020;
  std::string topic = "gaze.";
  int request_timeout_ms = 1000;               ///< each REQ send/recv
  int receive_timeout_ms = 100;                ///< each SUB recv (the thread's tick)
  double silence_s = 1.0;                      ///< no message this long: ask SUB_PORT again
  std::int64_t max_message_bytes = 64 * 1024;  ///< ZMQ_MAXMSGSIZE (per frame)
  std::size_t queue_limit = 0;     ///< samples kept for drain() (0: none, sample() only)
  double off_screen_limit = 0.25;  ///< SampleValidator's
};

struct PupilCounters {
  std::uint64_t messages = 0;         ///< gaze messages received
  std::uint64_t accepted = 0;         ///< samples that passed the validator
  std::uint64_t malformed = 0;        ///< bad msgpack, wrong shape, missing fields, too many parts
  std::uint64_t connects = 0;         ///< successful SUB_PORT handshakes (1 + reconnects)
  std::uint64_t failed_requests = 0;  ///< REQ exchanges that timed out or failed
  std::uint64_t overflow = 0;         ///< samples lost because drain() was not called
  DropCounts dropped;                 ///< from the shared SampleValidator
  bool connected = false;             ///< a handshake succeeded and the publisher is not silent
  /// Why the last handshake failed ("no answer to SUB_PORT", "the answer to
  /// SUB_PORT, '99999999', is not a valid port (1..65535)"); empty when none did.
  std::string last_failure;
  [[nodiscard]] std::string summary() const;
};

/// A decoded gaze datum (tracker clock, position already flipped to origin top-left).
struct PupilGaze {
  double timestamp = 0.0;
  Vec2d pos{};
  double confidence = 0.0;
};

/// Decodes one msgpack payload; nullopt when it is malformed (never throws).
/// Exposed for tests and tools.
std::optional<PupilGaze> decode_pupil_gaze(std::string_view payload);

/// "host:port", "host" or "" -> options (port 1..65535); throws foveate::Error.
PupilOptions parse_pupil_address(const std::string& address);

class PupilSource final : public GazeSource {
 public:
  explicit PupilSource(PupilOptions options = {});
  ~PupilSource() override;
  PupilSource(const PupilSource&) = delete;
  PupilSource& operator=(const PupilSource&) = delete;

  /// The newest sample, its time on the render clock (t_s is taken to run with
  /// the steady clock). Invalid with time t_s before the first sample.
  GazeSample sample(double t_s) override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] std::string report() const override;

  /// Every accepted sample since the last call, times in seconds on this
  /// source's steady clock (seconds since construction). With `arrival_s`,
  /// also when each arrived on that clock (arrival - time = transport latency).
  std::vector<GazeSample> drain(std::vector<double>* arrival_s = nullptr);
  /// Seconds since construction on the steady clock (the clock drain() uses).
  [[nodiscard]] double now_s() const;
  [[nodiscard]] PupilCounters counters() const;
  /// Blocks until a handshake succeeded or `timeout_s` passed; returns connected.
  bool wait_connected(double timeout_s) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace foveate::gaze
