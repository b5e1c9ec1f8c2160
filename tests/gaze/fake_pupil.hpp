#pragma once
// A local stand-in for Pupil Capture's network API, for tests: a REP socket on
// the control port answering SUB_PORT and t, and a PUB socket publishing
// [topic, msgpack] frames. Bound to 127.0.0.1 on ephemeral ports.
#include <atomic>
#include <mutex>
#include <string>
#include <thread>
#include <vector>
#include <zmq.hpp>

namespace foveate::gaze::testing {

class FakePupil {
 public:
  /// control_port 0: an ephemeral port.
  explicit FakePupil(double clock_offset_s = 1000.0, int control_port = 0);
  ~FakePupil();
  FakePupil(const FakePupil&) = delete;
  FakePupil& operator=(const FakePupil&) = delete;

  /// Stops answering and publishing (as if the tracker quit).
  void stop();
  /// Comes back on the same control port with a new publisher port and clock.
  void start(double clock_offset_s);

  [[nodiscard]] int control_port() const { return control_port_; }
  [[nodiscard]] int pub_port() const { return pub_port_; }
  /// The tracker's clock: the steady clock plus the offset.
  [[nodiscard]] double clock() const;

  /// Publishing is done from the test thread only.
  void publish(const std::vector<std::string>& parts);
  /// A gaze datum as Pupil sends it: norm_pos with origin bottom-left.
  void publish_gaze(double x, double y_bottom_left, double confidence, double timestamp);
  static std::string pack_gaze(double x, double y_bottom_left, double confidence, double timestamp);

  std::atomic<int> requests{0};

  /// Answers SUB_PORT with `answer` instead of the publisher's port (a
  /// misbehaving tracker); empty restores the real port.
  void answer_sub_port_with(std::string answer) {
    std::lock_guard<std::mutex> lock(answer_mu_);
    sub_port_answer_ = std::move(answer);
  }

 private:
  void serve();
  zmq::context_t ctx_{1};
  std::unique_ptr<zmq::socket_t> rep_, pub_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<double> offset_{0.0};
  int control_port_ = 0;
  int pub_port_ = 0;
  std::mutex answer_mu_;
  std::string sub_port_answer_;
};

/// A port on 127.0.0.1 with nothing listening (bound, then released).
int unused_port();

}  // namespace foveate::gaze::testing
