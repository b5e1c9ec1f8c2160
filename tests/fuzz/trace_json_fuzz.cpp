// Gaze trace JSON ({"format": "foveate-gaze", ...} or a bare sample array).
#include <cmath>

#include "foveate/gaze/trace.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace foveate::gaze;
  foveate::fuzz::expect_clean([&] {
    const Trace t = parse_trace_json(foveate::fuzz::text(data, size), "fuzz.json");
    foveate::fuzz::check(!t.samples.empty());
    for (size_t i = 1; i < t.samples.size(); ++i) {
      foveate::fuzz::check(t.samples[i].time_s > t.samples[i - 1].time_s);
    }
    for (double s : {0.0, 0.5 * t.duration_s(), t.duration_s() + 1.0}) {
      const GazeSample g = interpolate(t, s);
      foveate::fuzz::check(std::isfinite(g.pos.x) && std::isfinite(g.pos.y));
    }
    (void)trace_to_json(t);
  });
  return 0;
}
