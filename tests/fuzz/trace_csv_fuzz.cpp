// Gaze trace CSV (the project's form and Pupil's gaze_positions.csv): parse,
// then use the trace as a render would (interpolation, re-export).
#include <cmath>

#include "foveate/gaze/trace.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace foveate::gaze;
  foveate::fuzz::expect_clean([&] {
    TraceOptions o;
    // The options come from the file's last byte, so the corpus stays plain CSV.
    const unsigned k = size ? data[size - 1] : 0;
    o.time_unit = static_cast<TimeUnit>(k % 3);
    o.pos_unit = static_cast<PosUnit>((k / 3) % 3);
    const Trace t = parse_trace_csv(foveate::fuzz::text(data, size), "fuzz.csv", o);
    foveate::fuzz::check(!t.samples.empty());
    for (size_t i = 1; i < t.samples.size(); ++i) {
      foveate::fuzz::check(t.samples[i].time_s > t.samples[i - 1].time_s);
    }
    for (double s : {-1.0, 0.0, 0.5 * t.duration_s(), t.duration_s() + 1.0}) {
      const GazeSample g = interpolate(t, s, {0.1, TraceEnd::kLoop});
      foveate::fuzz::check(std::isfinite(g.pos.x) && std::isfinite(g.pos.y));
    }
    (void)trace_to_csv(t);
    (void)trace_to_json(t);
  });
  return 0;
}
