#include "foveate/gaze/gaze.hpp"

#include <cmath>
#include <cstdlib>
#include <utility>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "foveate/gaze/nearest_object.hpp"
#include "foveate/gaze/pupil.hpp"
#include "foveate/gaze/synthetic.hpp"
#include "foveate/gaze/trace.hpp"

namespace foveate::gaze {

Vec2d GazeSample::pixels(int width, int height) const { return {pos.x * width, pos.y * height}; }

double angle_between_deg(const Display& display, Vec2d a, Vec2d b) {
  const double w = display.width_px, h = display.height_px;
  return display.eccentricity_deg({a.x * w, a.y * h}, {b.x * w, b.y * h});
}

// ------------------------------------------------------------ dropped samples

const char* to_string(DropReason reason) {
  switch (reason) {
    case DropReason::kNonFinite:
      return "non-finite";
    case DropReason::kOutOfRange:
      return "out-of-range";
    case DropReason::kBackwards:
      return "backwards";
    case DropReason::kDuplicate:
      return "duplicate";
  }
  return "?";
}

void DropCounts::add(DropReason reason) {
  switch (reason) {
    case DropReason::kNonFinite:
      ++non_finite;
      break;
    case DropReason::kOutOfRange:
      ++out_of_range;
      break;
    case DropReason::kBackwards:
      ++backwards;
      break;
    case DropReason::kDuplicate:
      ++duplicate;
      break;
  }
}

DropCounts& DropCounts::operator+=(const DropCounts& o) {
  non_finite += o.non_finite;
  out_of_range += o.out_of_range;
  backwards += o.backwards;
  duplicate += o.duplicate;
  return *this;
}

std::string DropCounts::summary() const {
  if (total() == 0) return "none dropped";
  std::string s = std::to_string(total()) + " dropped (";
  bool first = true;
  auto part = [&](std::uint64_t n, const char* what) {
    if (n == 0) return;
    if (!first) s += ", ";
    s += std::to_string(n) + " " + what;
    first = false;
  };
  part(non_finite, "non-finite");
  part(out_of_range, "out-of-range");
  part(backwards, "backwards in time");
  part(duplicate, "duplicate time");
  return s + ")";
}

SampleValidator::SampleValidator(double off_screen_limit) : off_screen_limit_(off_screen_limit) {
  if (!(std::isfinite(off_screen_limit) && off_screen_limit >= 0.0 && off_screen_limit <= 10.0)) {
    throw Error("gaze off-screen limit: expected 0..10 screen sizes, got " +
                format_number(off_screen_limit));
  }
}

std::optional<DropReason> SampleValidator::check(const GazeSample& s) {
  std::optional<DropReason> r;
  if (!std::isfinite(s.time_s) || !std::isfinite(s.pos.x) || !std::isfinite(s.pos.y) ||
      !std::isfinite(s.confidence)) {
    r = DropReason::kNonFinite;
  } else if (s.pos.x < -off_screen_limit_ || s.pos.x > 1.0 + off_screen_limit_ ||
             s.pos.y < -off_screen_limit_ || s.pos.y > 1.0 + off_screen_limit_ ||
             s.confidence < 0.0 || s.confidence > 1.0) {
    r = DropReason::kOutOfRange;
  } else if (have_last_ && s.time_s < last_time_) {
    r = DropReason::kBackwards;
  } else if (have_last_ && s.time_s == last_time_) {
    r = DropReason::kDuplicate;
  }
  if (r) {
    counts_.add(*r);
    return r;
  }
  have_last_ = true;
  last_time_ = s.time_s;
  ++accepted_;
  return std::nullopt;
}

// ------------------------------------------------------------ simple sources

namespace {

class FixedSource final : public GazeSource {
 public:
  explicit FixedSource(Vec2d pos) : pos_(pos) {}
  GazeSample sample(double t_s) override { return {t_s, pos_, 1.0, true}; }
  std::string describe() const override {
    char buf[96];
    std::snprintf(buf, sizeof buf, "fixed at (%.3f, %.3f) normalized", pos_.x, pos_.y);
    return buf;
  }

 private:
  Vec2d pos_;
};

class MouseSource final : public GazeSource {
 public:
  explicit MouseSource(std::function<std::optional<Vec2d>()> mouse) : mouse_(std::move(mouse)) {}
  GazeSample sample(double t_s) override {
    const std::optional<Vec2d> p = mouse_();
    // Outside the window the mouse says nothing: invalid, like a lost eye.
    if (!p) return {t_s, last_, 0.0, false};
    last_ = *p;
    return {t_s, *p, 1.0, true};
  }
  std::string describe() const override { return "mouse"; }

 private:
  std::function<std::optional<Vec2d>()> mouse_;
  Vec2d last_{0.5, 0.5};
};

Vec2d parse_fixed(const std::string& text, int width, int height) {
  // A fixed gaze off the image would measure a technique's fallback, not foveation.
  const Vec2d px = parse_point_on_image(text, width, height, "fixed gaze point");
  return {px.x / width, px.y / height};
}

Vec2d parse_fixed(const std::string& text, const Display& d) {
  return parse_fixed(text, d.width_px, d.height_px);
}

// The kinds of source a spec may name.
const std::vector<std::string>& source_kinds() {
  static const std::vector<std::string> kinds{"fixed", "trace", "synthetic",
                                              "pupil", "mouse", "nearest"};
  return kinds;
}

}  // namespace

const char* gaze_spec_help() {
  return "X,Y or fixed:X,Y on the image (whole numbers are pixels: 960,540; numbers with a "
         "decimal point are normalized, 0.0..1.0: 0.5,0.5) | trace:FILE "
         "(CSV, Pupil gaze_positions.csv, "
         "JSON) | synthetic[:SEED] | pupil[:HOST[:PORT]] (default 127.0.0.1:50020) | mouse | "
         "nearest (the nearest scene object)";
}

std::unique_ptr<GazeSource> make_gaze_source(const std::string& spec, const GazeContext& ctx) {
  const auto colon = spec.find(':');
  const std::string kind = spec.substr(0, colon);
  const bool has_arg = colon != std::string::npos;
  const std::string arg = has_arg ? spec.substr(colon + 1) : std::string();
  if (spec.empty())
    throw Error("gaze source: empty spec; expected " + std::string(gaze_spec_help()));

  if (kind == "fixed") {
    if (!has_arg)
      throw Error("gaze source fixed: give the point, e.g. fixed:960,540 or fixed:0.5,0.5");
    return std::make_unique<FixedSource>(parse_fixed(arg, ctx.display));
  }
  if (!has_arg && spec.find(',') != std::string::npos) {
    return std::make_unique<FixedSource>(parse_fixed(spec, ctx.display));
  }
  if (kind == "trace") {
    if (arg.empty()) throw Error("gaze source trace: give the file, e.g. trace:gaze.csv");
    TraceOptions o;
    o.width_px = ctx.display.width_px;
    o.height_px = ctx.display.height_px;
    o.strict = ctx.strict_traces;
    Trace trace = load_trace(arg, o);
    if (ctx.warn) {
      for (const std::string& w : trace.warnings) ctx.warn(w);
    }
    return std::make_unique<TraceSource>(std::move(trace), arg);
  }
  if (kind == "synthetic") {
    SyntheticOptions o;
    if (has_arg) {
      char* end = nullptr;
      const unsigned long long seed = std::strtoull(arg.c_str(), &end, 10);
      if (arg.empty() || arg[0] == '-' || end != arg.c_str() + arg.size()) {
        throw Error("gaze source synthetic: the seed must be a non-negative integer, got '" + arg +
                    "'");
      }
      o.seed = seed;
    }
    return std::make_unique<SyntheticViewer>(ctx.display, o);
  }
  if (kind == "pupil") {
    return std::make_unique<PupilSource>(parse_pupil_address(arg));
  }
  if (kind == "mouse") {
    if (has_arg) throw Error("gaze source mouse takes no argument");
    if (!ctx.mouse) throw Error("gaze source mouse needs a window (foveate view)");
    return std::make_unique<MouseSource>(ctx.mouse);
  }
  if (kind == "nearest") {
    if (has_arg) throw Error("gaze source nearest takes no argument");
    if (!ctx.objects) throw Error("gaze source nearest needs a scene that knows its objects");
    return std::make_unique<NearestObjectViewer>(ctx.display, ctx.objects);
  }
  const std::string suggestion = did_you_mean(kind, source_kinds());
  throw Error("gaze source: unknown source '" + kind + "'" +
              (suggestion.empty() ? ";" : suggestion) + " expected " + gaze_spec_help());
}

void check_gaze_spec(const std::string& spec, int width, int height) {
  if (spec.empty()) return;
  const auto colon = spec.find(':');
  const std::string kind = spec.substr(0, colon);
  if (kind == "fixed" && colon != std::string::npos) {
    (void)parse_fixed(spec.substr(colon + 1), width, height);
  } else if (colon == std::string::npos && spec.find(',') != std::string::npos) {
    (void)parse_fixed(spec, width, height);
  }
}

}  // namespace foveate::gaze
