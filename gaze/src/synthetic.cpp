#include "foveate/gaze/synthetic.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include "foveate/core/error.hpp"

namespace foveate::gaze {

const char* to_string(Movement::Kind kind) {
  switch (kind) {
    case Movement::Kind::kFixation:
      return "fixation";
    case Movement::Kind::kSaccade:
      return "saccade";
    case Movement::Kind::kPursuit:
      return "pursuit";
    case Movement::Kind::kBlink:
      return "blink";
    case Movement::Kind::kMicrosaccade:
      return "microsaccade";
  }
  return "?";
}

// ------------------------------------------------------------ synthetic viewer

namespace {

Vec2d lerp(Vec2d a, Vec2d b, double u) { return {a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)}; }

/// splitmix64: a counter-based hash, for noise that depends only on (seed, index).
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

double unit_from(std::uint64_t x) { return (static_cast<double>(x >> 11) + 0.5) * 0x1.0p-53; }

struct Micro {
  double start = 0, dur = 0, a = 2, amplitude = 0, peak = 0;
  Vec2d delta{};
};

struct Segment {
  Movement m;
  double a = 2.0;            // saccade profile exponent
  Vec2d velocity{};          // pursuit, normalized per second
  std::vector<Vec2d> drift;  // fixation: offsets every kDriftStep from m.start_s
  std::vector<Micro> micro;  // fixation: microsaccades
};

constexpr double kDriftStep = 0.01;

}  // namespace

struct SyntheticViewer::Impl {
  Display display;
  SyntheticOptions o;
  std::mt19937_64 rng;
  std::vector<Segment> segments;
  double px_per_deg = 1.0;

  Impl(const Display& d, SyntheticOptions opt) : display(d), o(std::move(opt)), rng(o.seed) {
    display.validate();
    if (!(o.saccade_min_deg > 0 && o.saccade_max_deg >= o.saccade_min_deg &&
          o.fixation_mean_s > 0 && o.fixation_min_s > 0 && o.blink_max_s >= o.blink_min_s &&
          o.blink_min_s > 0 && o.pursuit_max_s >= o.pursuit_min_s && o.pursuit_min_s > 0 &&
          o.rate_hz >= 0 && o.latency_ms >= 0 && o.noise_deg >= 0 && o.edge_inset >= 0 &&
          o.edge_inset < 0.5)) {
      throw Error("synthetic viewer: inconsistent options");
    }
    px_per_deg = display.eye_distance_px() * std::tan(std::numbers::pi / 180.0);
  }

  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  double normal(double sd) { return std::normal_distribution<double>(0.0, sd)(rng); }
  Vec2d deg_to_norm(double dx, double dy) const {
    return {dx * px_per_deg / display.width_px, dy * px_per_deg / display.height_px};
  }
  Vec2d clamp_screen(Vec2d p) const {
    return {std::clamp(p.x, 0.0, 1.0), std::clamp(p.y, 0.0, 1.0)};
  }

  Vec2d end_of(const Segment& s) const { return s.m.to; }

  void push_fixation(double t0, Vec2d p0) {
    Segment s;
    s.m.kind = Movement::Kind::kFixation;
    s.m.start_s = t0;
    const double shape = 4.0;  // gamma with mean fixation_mean_s
    const double dur = std::max(
        o.fixation_min_s, std::gamma_distribution<double>(shape, o.fixation_mean_s / shape)(rng));
    s.m.end_s = t0 + dur;
    s.m.from = p0;
    const int steps = static_cast<int>(std::ceil(dur / kDriftStep)) + 1;
    Vec2d off{0, 0};
    const double sd = o.drift_deg_per_sqrt_s * std::sqrt(kDriftStep);
    s.drift.reserve(steps + 1);
    s.drift.push_back(off);
    for (int i = 0; i < steps; ++i) {
      const Vec2d d = deg_to_norm(normal(sd), normal(sd));
      off = {off.x + d.x, off.y + d.y};
      s.drift.push_back(off);
    }
    if (o.microsaccade_rate_hz > 0) {
      double t = t0 + std::exponential_distribution<double>(o.microsaccade_rate_hz)(rng);
      while (true) {
        Micro m;
        m.amplitude = uniform(0.1, std::max(0.11, o.microsaccade_max_deg));
        m.dur = o.main_sequence.duration_s(m.amplitude);
        if (t + m.dur >= s.m.end_s) break;
        m.start = t;
        m.peak = o.main_sequence.peak_velocity_deg_per_s(m.amplitude);
        m.a = profile_exponent_for_ratio(m.peak * m.dur / m.amplitude);
        const double dir = uniform(0.0, 2.0 * std::numbers::pi);
        m.delta = deg_to_norm(m.amplitude * std::cos(dir), m.amplitude * std::sin(dir));
        s.micro.push_back(m);
        t += m.dur + std::exponential_distribution<double>(o.microsaccade_rate_hz)(rng);
      }
    }
    s.m.to = clamp_screen(fixation_pos(s, s.m.end_s));
    segments.push_back(std::move(s));
  }

  Vec2d fixation_pos(const Segment& s, double t) const {
    const double x = std::max(0.0, (t - s.m.start_s) / kDriftStep);
    const size_t i = std::min(static_cast<size_t>(x), s.drift.size() - 2);
    const double f = std::min(1.0, x - static_cast<double>(i));
    const Vec2d d = lerp(s.drift[i], s.drift[i + 1], f);
    Vec2d p{s.m.from.x + d.x, s.m.from.y + d.y};
    for (const Micro& m : s.micro) {
      if (t <= m.start) break;
      const double u = profile_position((t - m.start) / m.dur, m.a);
      p = {p.x + u * m.delta.x, p.y + u * m.delta.y};
    }
    return p;
  }

  void push_saccade(double t0, Vec2d p0) {
    const double lo = o.edge_inset, hi = 1.0 - o.edge_inset;
    Vec2d target = p0;
    double amp = 0;
    for (int tries = 0; tries < 32; ++tries) {
      target = {uniform(lo, hi), uniform(lo, hi)};
      amp = angle_between_deg(display, p0, target);
      if (amp >= o.saccade_min_deg && amp <= o.saccade_max_deg) break;
    }
    Segment s;
    s.m.kind = Movement::Kind::kSaccade;
    s.m.start_s = t0;
    s.m.from = p0;
    s.m.to = target;
    s.m.amplitude_deg = amp;
    const double dur = o.main_sequence.duration_s(amp);
    s.m.end_s = t0 + dur;
    s.m.peak_deg_per_s = o.main_sequence.peak_velocity_deg_per_s(amp);
    s.a = amp > 0 ? profile_exponent_for_ratio(s.m.peak_deg_per_s * dur / amp) : 2.0;
    segments.push_back(std::move(s));
  }

  void push_pursuit(double t0, Vec2d p0) {
    Segment s;
    s.m.kind = Movement::Kind::kPursuit;
    s.m.start_s = t0;
    s.m.from = p0;
    const double speed = uniform(o.pursuit_min_deg_per_s, o.pursuit_max_deg_per_s);
    double dur = uniform(o.pursuit_min_s, o.pursuit_max_s);
    const double lo = o.edge_inset, hi = 1.0 - o.edge_inset;
    Vec2d v{};
    for (int tries = 0; tries < 16; ++tries) {
      const double dir = uniform(0.0, 2.0 * std::numbers::pi);
      v = deg_to_norm(speed * std::cos(dir), speed * std::sin(dir));
      const Vec2d end{p0.x + v.x * dur, p0.y + v.y * dur};
      if (end.x >= lo && end.x <= hi && end.y >= lo && end.y <= hi) break;
      if (tries == 15) dur = o.pursuit_min_s * 0.5;  // cornered: a short pursuit
    }
    s.velocity = v;
    s.m.end_s = t0 + dur;
    s.m.to = clamp_screen({p0.x + v.x * dur, p0.y + v.y * dur});
    segments.push_back(std::move(s));
  }

  void push_blink(double t0, Vec2d p0) {
    Segment s;
    s.m.kind = Movement::Kind::kBlink;
    s.m.start_s = t0;
    s.m.end_s = t0 + uniform(o.blink_min_s, o.blink_max_s);
    s.m.from = s.m.to = p0;
    segments.push_back(std::move(s));
  }

  void generate_until(double t) {
    if (segments.empty()) push_fixation(0.0, {0.5, 0.5});
    while (segments.back().m.end_s <= t) {
      const Segment& last = segments.back();
      const double t0 = last.m.end_s;
      const Vec2d p0 = end_of(last);
      if (last.m.kind != Movement::Kind::kFixation) {
        push_fixation(t0, p0);
        continue;
      }
      const double r = uniform(0.0, 1.0);
      const double p_blink = std::min(0.5, o.blink_rate_hz * o.fixation_mean_s);
      if (r < p_blink) {
        push_blink(t0, p0);
      } else if (r < p_blink + o.pursuit_probability) {
        push_pursuit(t0, p0);
      } else {
        push_saccade(t0, p0);
      }
    }
  }

  // Only the behaviour around the latest query is kept: a render asks for the
  // gaze frame by frame, and a history kept whole grew by ~30 bytes a frame
  // (a fixation's drift path is ~400 bytes). The generator's state is the RNG
  // alone, so dropping old segments does not change what comes next, and a
  // query before what is kept regenerates from the seed (same result).
  static constexpr size_t kPruneAt = 64;  ///< segments kept before pruning
  static constexpr double kKeepS = 10.0;  ///< behaviour kept before the latest query

  void restart() {
    segments.clear();
    rng.seed(o.seed);
  }

  void prune(double t) {
    if (segments.size() <= kPruneAt) return;
    auto keep = std::find_if(segments.begin(), segments.end() - 1,
                             [&](const Segment& s) { return s.m.end_s >= t - kKeepS; });
    segments.erase(segments.begin(), keep);
  }

  const Segment& segment_at(double t) {
    if (!segments.empty() && t < segments.front().m.start_s) restart();
    generate_until(t);
    prune(t);
    auto it = std::upper_bound(segments.begin(), segments.end(), t,
                               [](double x, const Segment& s) { return x < s.m.start_s; });
    return it == segments.begin() ? segments.front() : *(it - 1);
  }

  GazeSample eye(double t) {
    t = std::max(0.0, t);
    const Segment& s = segment_at(t);
    switch (s.m.kind) {
      case Movement::Kind::kFixation:
        return {t, clamp_screen(fixation_pos(s, t)), 1.0, true};
      case Movement::Kind::kSaccade:
        return {t,
                lerp(s.m.from, s.m.to,
                     profile_position((t - s.m.start_s) / (s.m.end_s - s.m.start_s), s.a)),
                1.0, true};
      case Movement::Kind::kPursuit:
        return {t,
                clamp_screen({s.m.from.x + s.velocity.x * (t - s.m.start_s),
                              s.m.from.y + s.velocity.y * (t - s.m.start_s)}),
                1.0, true};
      case Movement::Kind::kBlink:
      case Movement::Kind::kMicrosaccade:
        break;
    }
    return {t, s.m.from, 0.0, false};
  }
};

SyntheticViewer::SyntheticViewer(const Display& display, SyntheticOptions options)
    : impl_(std::make_unique<Impl>(display, std::move(options))) {}
SyntheticViewer::~SyntheticViewer() = default;

GazeSample SyntheticViewer::eye(double t_s) { return impl_->eye(t_s); }

GazeSample SyntheticViewer::sample(double t_s) {
  const SyntheticOptions& o = impl_->o;
  double ts = t_s - o.latency_ms * 1e-3;
  std::uint64_t index = 0;
  if (o.rate_hz > 0) {
    const double k = std::floor(std::max(0.0, ts) * o.rate_hz);
    index = static_cast<std::uint64_t>(k);
    ts = k / o.rate_hz;
  } else {
    index = static_cast<std::uint64_t>(std::max(0.0, ts) * 1e6);
  }
  GazeSample s = impl_->eye(std::max(0.0, ts));
  s.time_s = ts;
  if (o.noise_deg > 0 && s.valid) {
    const std::uint64_t h = mix(o.seed ^ mix(index));
    const double u1 = unit_from(h), u2 = unit_from(mix(h));
    const double r = std::sqrt(-2.0 * std::log(u1)) * o.noise_deg;
    const Vec2d n = impl_->deg_to_norm(r * std::cos(2 * std::numbers::pi * u2),
                                       r * std::sin(2 * std::numbers::pi * u2));
    s.pos = {s.pos.x + n.x, s.pos.y + n.y};
  }
  return s;
}

std::vector<Movement> SyntheticViewer::movements_until(double t_s) {
  // From the start on a generator of its own (the viewer keeps only the
  // recent behaviour); the same seed gives the same movements.
  Impl all(impl_->display, impl_->o);
  all.generate_until(t_s);
  std::vector<Movement> out;
  for (const Segment& s : all.segments) {
    if (s.m.start_s >= t_s) break;
    out.push_back(s.m);
    for (const Micro& m : s.micro) {
      Movement mm;
      mm.kind = Movement::Kind::kMicrosaccade;
      mm.start_s = m.start;
      mm.end_s = m.start + m.dur;
      mm.amplitude_deg = m.amplitude;
      mm.peak_deg_per_s = m.peak;
      out.push_back(mm);
    }
  }
  return out;
}

std::string SyntheticViewer::describe() const {
  const SyntheticOptions& o = impl_->o;
  std::string s = "synthetic viewer (seed " + std::to_string(o.seed);
  if (o.rate_hz > 0) s += ", " + std::to_string(static_cast<int>(o.rate_hz)) + " Hz";
  if (o.latency_ms > 0) s += ", " + std::to_string(static_cast<int>(o.latency_ms)) + " ms latency";
  return s + ")";
}

}  // namespace foveate::gaze
