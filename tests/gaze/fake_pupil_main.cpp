// foveate_fake_pupil SECONDS [SUB_PORT_ANSWER]: a local Pupil Capture stand-in for command-line
// tests. Prints its control port, then publishes gaze at 200 Hz (a circle,
// with one malformed frame a second) on 127.0.0.1 for SECONDS, then exits.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "fake_pupil.hpp"

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 3.0;
  if (!(seconds > 0 && seconds <= 60)) {
    std::fprintf(stderr, "usage: foveate_fake_pupil SECONDS (0..60)\n");
    return 2;
  }
  foveate::gaze::testing::FakePupil fake(500.0);
  if (argc > 2) fake.answer_sub_port_with(argv[2]);  // a misbehaving tracker
  std::printf("%d\n", fake.control_port());
  std::fflush(stdout);
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0;; ++k) {
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (t > seconds) break;
    fake.publish_gaze(0.5 + 0.2 * std::cos(t), 0.5 + 0.2 * std::sin(t), 0.95, fake.clock());
    if (k % 200 == 199) fake.publish({"gaze.2d.0.", "not msgpack"});
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return 0;
}
