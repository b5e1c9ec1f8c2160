// FovVideoVDP at 1920x1080 on one core: the work of `foveate compare` per
// frame of two folders of frames (decoding two PNGs, their luminance and the
// metric), the metric alone with a fixed and with a moving gaze, and a single
// image pair (which includes building the metric). The target is at most
// 0.25 s per frame. "peak_rss_mib" shows that memory is bounded by the
// temporal window (250 ms of frames), not by the number of frames.
//   ./build/release/benchmarks/foveate_fvvdp_bench
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "foveate/core/image.hpp"
#include "foveate/metrics/fvvdp.hpp"

namespace {

using foveate::Display;
using foveate::Image;
using foveate::metrics::Fvvdp;

// A frame with detail at every scale (so that no band is trivially empty),
// moving with the frame number, and a test version with mild noise.
Image frame(int index, bool noisy) {
  Image img(1920, 1080);
  std::uint32_t seed = 12345u + static_cast<std::uint32_t>(index);
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const double u = x + 3.0 * index;
      double v = 0.45 + 0.2 * std::sin(u * 0.9) * std::sin(y * 0.7) +
                 0.15 * std::sin(u * 0.013 + y * 0.02) + (((x / 97 + y / 61) % 2) ? 0.08 : -0.08);
      if (noisy) {
        seed = seed * 1664525u + 1013904223u;
        v += ((seed >> 8) / 16777216.0 - 0.5) * 0.04;
      }
      const auto c =
          static_cast<std::uint8_t>(std::lround(std::fmin(std::fmax(v, 0.0), 1.0) * 255.0));
      std::uint8_t* p = img.at(x, y);
      p[0] = p[1] = p[2] = c;
      p[3] = 255;
    }
  }
  return img;
}

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

const Display& display() {
  static const Display d = Display::load("desktop-1080p");
  return d;
}

// What `foveate compare REF_DIR TEST_DIR` does per frame.
void compare_png_frames(benchmark::State& state) {
  const std::string dir = (std::filesystem::temp_directory_path() / "foveate_fvvdp_bench").string();
  std::filesystem::create_directories(dir);
  for (int i = 0; i < 4; ++i) {
    foveate::write_png(dir + "/ref-" + std::to_string(i) + ".png", frame(i, false));
    foveate::write_png(dir + "/test-" + std::to_string(i) + ".png", frame(i, true));
  }
  Fvvdp metric(display());
  int i = 0;
  for (auto _ : state) {
    const Image ref = foveate::read_image(dir + "/ref-" + std::to_string(i % 4) + ".png");
    const Image test = foveate::read_image(dir + "/test-" + std::to_string(i % 4) + ".png");
    metric.add(test, ref, {960, 540});
    ++i;
  }
  benchmark::DoNotOptimize(metric.result().jod);
  state.counters["peak_rss_mib"] = peak_rss_mib();
  std::filesystem::remove_all(dir);
}

void video_frame(benchmark::State& state, bool moving_gaze) {
  const Image refs[2] = {frame(0, false), frame(1, false)};
  const Image tests[2] = {frame(0, true), frame(1, true)};
  Fvvdp metric(display());
  int i = 0;
  for (auto _ : state) {
    const foveate::Vec2d gaze =
        moving_gaze ? foveate::Vec2d{600.0 + 7.0 * (i % 100), 540.0} : foveate::Vec2d{960, 540};
    metric.add(tests[i % 2], refs[i % 2], gaze);
    ++i;
  }
  benchmark::DoNotOptimize(metric.result().jod);
  state.counters["peak_rss_mib"] = peak_rss_mib();
}

void image_pair(benchmark::State& state) {
  const Image ref = frame(0, false), test = frame(0, true);
  for (auto _ : state) {
    benchmark::DoNotOptimize(foveate::metrics::fvvdp_image(test, ref, display(), {960, 540}).jod);
  }
}

}  // namespace

BENCHMARK(compare_png_frames)->Unit(benchmark::kMillisecond)->MinTime(8.0);
BENCHMARK_CAPTURE(video_frame, fixed_gaze, false)->Unit(benchmark::kMillisecond)->MinTime(8.0);
BENCHMARK_CAPTURE(video_frame, moving_gaze, true)->Unit(benchmark::kMillisecond)->MinTime(8.0);
BENCHMARK(image_pair)->Unit(benchmark::kMillisecond)->MinTime(3.0);
