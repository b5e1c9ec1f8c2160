#include "messages.hpp"

#include <unistd.h>

#include <cstdio>
#include <map>

#include "cli_util.hpp"
#include "output_dir.hpp"

namespace foveate::app {

std::string flag_for(const std::string& field) {
  static const std::map<std::string, std::string> flags = {
      {"acuity_preset", "--acuity"},
      {"allow_fallback", "--allow-fallback"},
      {"bound_jod", "--bound"},
      {"camera_path", "--camera-path"},
      {"channels", "--channel"},
      {"display", "--display"},
      {"fps", "--fps"},
      {"frame_timeout_s", "--frame-timeout"},
      {"frames", "--frames"},
      {"gaze", "--gaze"},
      {"image_metrics", "--no-metrics"},
      {"margin", "--margin"},
      {"memory_limit", "--memory-limit"},
      {"out", "--out"},
      {"params", "--param"},
      {"photometry.ambient_lux", "--ambient-lux"},
      {"photometry.contrast_ratio", "--contrast-ratio"},
      {"photometry.peak_cd_m2", "--peak-luminance"},
      {"photometry.reflectivity", "--reflectivity"},
      {"reference", "--reference"},
      {"scene", "--scene"},
      {"scenes", "--scenes"},
      {"shard", "--shard"},
      {"side_by_side", "--side-by-side"},
      {"size", "--size"},
      {"slope", "--slope"},
      {"start_time_s", "--time"},
      {"stereo", "--stereo"},
      {"sweep", "--sweep"},
      {"techniques", "--techniques"},
      {"up", "--up"},
      {"values", "--values"},
      {"vergence_m", "--vergence"},
      {"video", "--video"},
      {"warmup", "--warmup"},
  };
  const auto it = flags.find(field);
  return it == flags.end() ? std::string() : it->second;
}

std::string with_flags(const bench::FieldText& text) { return text.render(flag_for); }

void print_notice(const bench::Notice& n) {
  switch (n.kind) {
    case bench::NoticeKind::Detail:
      if (verbose()) std::fprintf(stderr, "foveate: %s\n", with_flags(n.text).c_str());
      return;
    case bench::NoticeKind::Note:
      if (!quiet()) std::fprintf(stderr, "foveate: note: %s\n", with_flags(n.text).c_str());
      return;
    case bench::NoticeKind::Warning:
      if (!quiet()) std::fprintf(stderr, "foveate: warning: %s\n", with_flags(n.text).c_str());
      return;
  }
}

bench::SessionCallbacks session_callbacks() {
  bench::SessionCallbacks c;
  c.notice = print_notice;
  c.frame_timeout = [](const bench::FieldText& error) {
    // The frame is stuck inside the GL: nothing on the main thread can return
    // from the draw, so the process ends here (buffered output first).
    std::fflush(stdout);
    std::fprintf(stderr,
                 "foveate: error: %s. A GL draw cannot be interrupted, so foveate exits here; "
                 "raise --frame-timeout for a slow scene or size (0 = no limit)\n",
                 with_flags(error).c_str());
    std::fflush(stderr);
    end_output_dirs_now();
    ::_exit(1);
  };
  return c;
}

}  // namespace foveate::app
