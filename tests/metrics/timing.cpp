// Times each metric on a 1920x1080 pair (not a test; run by hand:
// foveate_metrics_timing [repeats]). Build with -O2 (Release) for real numbers.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>

#include "foveate/metrics/metrics.hpp"

using namespace foveate;
using namespace foveate::metrics;

namespace {

Image pattern(int w, int h, unsigned seed) {
  Image img(w, h);
  unsigned s = seed;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      s = s * 1664525u + 1013904223u;
      std::uint8_t* p = img.at(x, y);
      p[0] = static_cast<std::uint8_t>(((x / 7 + y / 5) % 2) * 150 + (s >> 27));
      p[1] = static_cast<std::uint8_t>((x * 255) / w);
      p[2] = static_cast<std::uint8_t>((s >> 24) & 0xff);
      p[3] = 255;
    }
  return img;
}

double time_ms(int repeats, const std::function<void()>& f) {
  double best = 1e30;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 3;
  const Display d = Display{};
  const Vec2d gaze{700, 400};
  const Image a = pattern(1920, 1080, 1), b = pattern(1920, 1080, 2);
  QualityOptions o;
  volatile double sink = 0;
  std::printf("1920x1080, best of %d (ms)\n", repeats);
  std::printf("psnr               %8.1f\n", time_ms(repeats, [&] { sink = psnr_db(a, b); }));
  std::printf("ssim               %8.1f\n", time_ms(repeats, [&] { sink = ssim(a, b); }));
  std::printf("eccentricity map   %8.1f\n",
              time_ms(repeats, [&] { sink = eccentricity_map(d, gaze).values[0]; }));
  std::printf("acuity cutoff map  %8.1f\n",
              time_ms(repeats, [&] { sink = acuity_cutoff_map(d, gaze, o.acuity).values[0]; }));
  std::printf("acuity difference  %8.1f\n", time_ms(repeats, [&] {
                sink = acuity_difference(a, b, d, gaze, o.acuity).values[0];
              }));
  std::printf("jnd map            %8.1f\n",
              time_ms(repeats, [&] { sink = jnd_map(a, b, d, gaze, o).values[0]; }));
  std::printf("flip               %8.1f\n",
              time_ms(repeats, [&] { sink = flip_map(a, b, 38.8).values[0]; }));
  FlickerTracker ft(d);
  std::printf("flicker add        %8.1f\n", time_ms(repeats, [&] { ft.add(a, b, gaze); }));
  std::printf("compare (all)      %8.1f\n",
              time_ms(repeats, [&] { sink = compare(a, b, d, gaze, o).psnr_db; }));
  o.flip = false;
  std::printf("compare (no flip)  %8.1f\n",
              time_ms(repeats, [&] { sink = compare(a, b, d, gaze, o).psnr_db; }));
  (void)sink;
  return 0;
}
