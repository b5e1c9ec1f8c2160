#include "foveate/metrics/fvvdp.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "fvvdp/band_judge.hpp"
#include "fvvdp/kernels.hpp"

namespace foveate::metrics {

namespace {

using fvvdp::BandJudge;
using fvvdp::FrameChannels;
using fvvdp::FrameDifference;

double srgb_to_linear(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

void validate(const FvvdpOptions& o) {
  if (!std::isfinite(o.fps) || o.fps <= 4.0 || o.fps > 1000.0) {
    throw Error("fvvdp.fps: must be in (4, 1000] frames per second, got " + format_number(o.fps));
  }
  for (size_t i = 0; i < o.band_edges_deg.size(); ++i) {
    const double e = o.band_edges_deg[i];
    if (!std::isfinite(e) || e < 0.0 || (i > 0 && e <= o.band_edges_deg[i - 1])) {
      throw Error("fvvdp.band_edges_deg: must be ascending and >= 0, got " + format_number(e) +
                  " at position " + std::to_string(i));
    }
  }
}

// The sustained and transient temporal filters of the paper (eq. 3 and its
// derivative), sampled over the 250 ms before a frame at the frame rate;
// element 0 weighs the newest frame.
std::array<std::vector<float>, 2> temporal_filters(double fps, const FvvdpParameters& p) {
  const int n = static_cast<int>(std::ceil(250.0 / (1000.0 / fps)));
  std::vector<double> t(static_cast<size_t>(n)), f0(static_cast<size_t>(n));
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    t[static_cast<size_t>(k)] = k * (n / fps) / (n - 1);
    const double d = std::log(t[static_cast<size_t>(k)] + 1e-4) - std::log(p.sustained_beta);
    f0[static_cast<size_t>(k)] = std::exp(-d * d / (2.0 * p.sustained_sigma * p.sustained_sigma));
    sum += f0[static_cast<size_t>(k)];
  }
  std::array<std::vector<float>, 2> f;
  for (int k = 0; k < n; ++k) {
    f[0].push_back(static_cast<float>(f0[static_cast<size_t>(k)] / sum));
  }
  // The transient filter is the sustained one's derivative, scaled by k2.
  constexpr double k2 = 0.062170507756932;
  const double dt = t[1] - t[0];
  for (int k = 0; k < n; ++k) {
    const double diff =
        k + 1 < n ? (f0[static_cast<size_t>(k + 1)] - f0[static_cast<size_t>(k)]) / sum : 0.0;
    f[1].push_back(static_cast<float>(k2 * diff / dt));
  }
  return f;
}

// The pooled difference of one frame: over bands (per temporal channel,
// transient weighted), then over the channels.
double pool_frame(const std::vector<std::array<double, 2>>& mean_dbeta, bool video,
                  const FvvdpParameters& p) {
  double channels = 0.0;
  for (int cc = 0; cc < 2; ++cc) {
    const double w = (video && cc == 1) ? p.w_transient : 1.0;
    double bands = 0.0;
    for (const auto& m : mean_dbeta) {
      bands += std::pow(w * std::pow(m[static_cast<size_t>(cc)], 1.0 / p.beta), p.beta_sch);
    }
    channels += std::pow(std::pow(bands, 1.0 / p.beta_sch), p.beta_tch);
  }
  return std::pow(channels, 1.0 / p.beta_tch);
}

double pool_frames(const std::vector<double>& q, const FvvdpParameters& p) {
  double sum = 0.0;
  int n = 0;
  for (double v : q) {
    if (std::isnan(v)) continue;
    sum += std::pow(v, p.beta_t);
    ++n;
  }
  return n == 0 ? std::nan("") : std::pow(sum / n, 1.0 / p.beta_t);
}

}  // namespace

double fvvdp_jod_from_difference(double q, const FvvdpParameters& p) {
  const double b = std::pow(10.0, p.log_jod_exp);
  const double sign = p.jod_a < 0.0 ? -1.0 : 1.0;
  return sign * std::pow(std::pow(std::abs(p.jod_a), 1.0 / b) * q, b) + 10.0;
}

Map display_luminance(const Image& image, const Photometry& photometry) {
  Map out;
  display_luminance(image, photometry, out);
  return out;
}

void display_luminance(const Image& image, const Photometry& photometry, Map& out) {
  // Y of linear sRGB (Rec. 709 primaries, D65) through the display: each
  // channel's share of the luminance, in cd/m^2, per code.
  const double black = photometry.black_cd_m2(), range = photometry.peak_cd_m2 - black;
  std::array<std::array<float, 256>, 3> share{};
  constexpr double weights[3] = {0.2126729, 0.7151522, 0.0721750};
  for (size_t c = 0; c < 3; ++c) {
    for (int i = 0; i < 256; ++i) {
      share[c][static_cast<size_t>(i)] =
          static_cast<float>(range * weights[c] * srgb_to_linear(i / 255.0));
    }
  }
  const auto b = static_cast<float>(black);
  out.width = image.width;
  out.height = image.height;
  out.values.resize(static_cast<size_t>(image.width) * image.height);
  const size_t n = out.values.size();
  const std::uint8_t* px = image.rgba.data();
  for (size_t i = 0; i < n; ++i, px += 4) {
    out.values[i] = share[0][px[0]] + share[1][px[1]] + share[2][px[2]] + b;
  }
}

struct Fvvdp::State {
  Display display;
  FvvdpOptions options;
  FvvdpParameters parameters;
  BandJudge judge;
  std::array<std::vector<float>, 2> filters;
  // The frames the temporal filters reach, oldest first (video mode).
  std::vector<std::shared_ptr<Map>> window_test, window_reference;
  // The first frame, held until a second one says the input is a video.
  std::shared_ptr<Map> first_test, first_reference;
  Vec2d first_gaze{};
  int frames = 0;
  std::vector<double> frame_q;                 // per frame
  std::vector<std::vector<double>> ecc_q;      // [ecc band][frame]
  std::vector<std::vector<double>> ecc_share;  // [ecc band][frame]
  Map heat_sum, worst_heat;
  int heat_frames = 0;
  FrameChannels channels;  // the filtered frame, reused
  double worst_q = -1.0;
  int worst_frame = -1;

  State(const Display& d, const FvvdpOptions& o, const FvvdpParameters& p)
      : display(d), options(o), parameters(p), judge(d, o, p) {
    filters = temporal_filters(o.fps, p);
    ecc_q.resize(o.band_edges_deg.size());
    ecc_share.resize(o.band_edges_deg.size());
  }

  // Pools one judged frame into the running results.
  void record(const FrameDifference& d, bool video, Vec2d gaze, std::vector<double>& q,
              std::vector<std::vector<double>>& eq, std::vector<std::vector<double>>& share,
              Map& heat, int& heat_count, Map& worst, double& worst_value, int& worst_index,
              int index) const {
    const double fq = pool_frame(d.mean, video, parameters);
    q.push_back(fq);
    const std::vector<double> shares = judge.ecc_band_fractions(gaze);
    for (size_t e = 0; e < eq.size(); ++e) {
      const bool empty = d.ecc_samples[e][0] == 0.0;
      eq[e].push_back(empty ? std::nan("") : pool_frame(d.by_ecc[e], video, parameters));
      share[e].push_back(shares[e]);
    }
    if (!d.distortion.values.empty()) {
      if (heat.values.empty()) heat = Map(d.distortion.width, d.distortion.height, 0.0f);
      for (size_t i = 0; i < heat.values.size(); ++i) heat.values[i] += d.distortion.values[i];
      ++heat_count;
      if (fq > worst_value) {
        worst_value = fq;
        worst_index = index;
        worst = d.distortion;
      }
    }
  }

  void judge_video_frame(Vec2d gaze) {
    const size_t n = window_test.size();
    FrameChannels& ch = channels;
    if (ch.planes.size() != 4) ch.planes.assign(4, Map(display.width_px, display.height_px));
    const size_t pixels = ch.planes[0].values.size();
    std::vector<const float*> test(n), reference(n);
    for (size_t k = 0; k < n; ++k) {
      test[k] = window_test[k]->values.data();
      reference[k] = window_reference[k]->values.data();
    }
    // Planes: test sustained, reference sustained, test transient, reference transient.
    fvvdp::temporal_filter(test.data(), n, filters[0].data(), filters[1].data(), pixels,
                           ch.planes[0].values.data(), ch.planes[2].values.data());
    fvvdp::temporal_filter(reference.data(), n, filters[0].data(), filters[1].data(), pixels,
                           ch.planes[1].values.data(), ch.planes[3].values.data());
    const FrameDifference d = judge.judge(ch, gaze, options.heatmap);
    record(d, true, gaze, frame_q, ecc_q, ecc_share, heat_sum, heat_frames, worst_heat, worst_q,
           worst_frame,
           frames - 1);
  }

  void add(std::shared_ptr<Map> t, std::shared_ptr<Map> r, Vec2d gaze_px);

  void push(std::shared_ptr<Map> test, std::shared_ptr<Map> reference) {
    for (auto* window : {&window_test, &window_reference}) {
      // A frame that leaves the window lends its storage to a coming one.
      std::shared_ptr<Map> leaving = std::move(window->front());
      window->erase(window->begin());
      if (leaving.use_count() == 1 && spare.size() < 2) spare.push_back(std::move(leaving));
    }
    window_test.push_back(std::move(test));
    window_reference.push_back(std::move(reference));
  }

  // A frame's storage: a spare one when there is one (no allocation, no page faults).
  std::shared_ptr<Map> take_frame() {
    if (spare.empty()) return std::make_shared<Map>();
    std::shared_ptr<Map> m = std::move(spare.back());
    spare.pop_back();
    return m;
  }
  std::vector<std::shared_ptr<Map>> spare;
};

Fvvdp::Fvvdp(const Display& display, FvvdpOptions options, FvvdpParameters parameters) {
  display.validate();
  validate(options);
  state_ = std::make_unique<State>(display, options, parameters);
}

Fvvdp::~Fvvdp() = default;
Fvvdp::Fvvdp(Fvvdp&&) noexcept = default;
Fvvdp& Fvvdp::operator=(Fvvdp&&) noexcept = default;

int Fvvdp::frames() const { return state_->frames; }
void Fvvdp::set_heatmap(bool on) { state_->options.heatmap = on; }
double Fvvdp::pixels_per_degree() const { return state_->judge.pixels_per_degree(); }

void Fvvdp::add(const Image& test, const Image& reference, Vec2d gaze_px) {
  const Photometry& p = state_->display.photometry;
  std::shared_ptr<Map> t = state_->take_frame(), r = state_->take_frame();
  display_luminance(test, p, *t);
  display_luminance(reference, p, *r);
  state_->add(std::move(t), std::move(r), gaze_px);
}

void Fvvdp::add_luminance(const Map& test, const Map& reference, Vec2d gaze_px) {
  std::shared_ptr<Map> t = state_->take_frame(), r = state_->take_frame();
  *t = test;
  *r = reference;
  state_->add(std::move(t), std::move(r), gaze_px);
}

void Fvvdp::State::add(std::shared_ptr<Map> t, std::shared_ptr<Map> r, Vec2d gaze_px) {
  State& s = *this;
  const Map& test = *t;
  const Map& reference = *r;
  const int w = s.display.width_px, h = s.display.height_px;
  for (const Map* m : {&test, &reference}) {
    if (m->width != w || m->height != h) {
      throw Error("FovVideoVDP: frame " + std::to_string(s.frames) + " is " +
                  std::to_string(m->width) + "x" + std::to_string(m->height) + ", the display is " +
                  std::to_string(w) + "x" + std::to_string(h));
    }
  }
  if (!std::isfinite(gaze_px.x) || !std::isfinite(gaze_px.y)) {
    throw Error("FovVideoVDP: frame " + std::to_string(s.frames) + ": the gaze is not finite");
  }
  ++s.frames;
  if (s.frames == 1) {
    s.first_test = std::move(t);
    s.first_reference = std::move(r);
    s.first_gaze = gaze_px;
    return;
  }
  if (s.frames == 2) {
    // A video: the filters see the first frame repeated before it.
    const size_t n = s.filters[0].size();
    s.window_test.assign(n, s.first_test);
    s.window_reference.assign(n, s.first_reference);
    --s.frames;
    s.judge_video_frame(s.first_gaze);
    ++s.frames;
    s.first_test.reset();
    s.first_reference.reset();
  }
  s.push(std::move(t), std::move(r));
  s.judge_video_frame(gaze_px);
}

FvvdpResult Fvvdp::result() const {
  const State& s = *state_;
  if (s.frames == 0) throw Error("FovVideoVDP: no frames");
  FvvdpResult out;
  out.frames = s.frames;
  out.image = s.frames == 1;
  out.fps = out.image ? 0.0 : s.options.fps;
  out.foveated = s.options.foveated;
  out.pixels_per_degree = s.judge.pixels_per_degree();
  out.photometry = s.display.photometry;

  std::vector<double> q = s.frame_q;
  std::vector<std::vector<double>> eq = s.ecc_q, share = s.ecc_share;
  Map heat = s.heat_sum, worst = s.worst_heat;
  int heat_frames = s.heat_frames;
  double worst_q = s.worst_q;
  int worst_frame = s.worst_frame;
  if (out.image) {
    FrameChannels ch;
    ch.planes = {*s.first_test, *s.first_reference};
    const FrameDifference d = s.judge.judge(ch, s.first_gaze, s.options.heatmap);
    s.record(d, false, s.first_gaze, q, eq, share, heat, heat_frames, worst, worst_q, worst_frame,
             0);
  }
  out.jod = fvvdp_jod_from_difference(pool_frames(q, s.parameters), s.parameters);
  for (double v : q) out.frame_jod.push_back(fvvdp_jod_from_difference(v, s.parameters));
  const auto& edges = s.options.band_edges_deg;
  for (size_t e = 0; e < edges.size(); ++e) {
    FvvdpBand b;
    b.from_deg = edges[e];
    if (e + 1 < edges.size()) b.to_deg = edges[e + 1];
    const double qe = pool_frames(eq[e], s.parameters);
    b.jod = std::isnan(qe) ? qe : fvvdp_jod_from_difference(qe, s.parameters);
    double sum = 0.0;
    for (double v : share[e]) sum += v;
    b.pixels_fraction = share[e].empty() ? 0.0 : sum / static_cast<double>(share[e].size());
    out.bands.push_back(b);
  }
  if (heat_frames > 0) {
    for (float& v : heat.values) v /= static_cast<float>(heat_frames);
    out.heatmap = std::move(heat);
    out.worst_heatmap = std::move(worst);
    out.worst_frame = worst_frame;
  }
  return out;
}

Image fvvdp_heatmap_image(const Map& distortion, const Image& reference, double max_jod) {
  if (distortion.width != reference.width || distortion.height != reference.height) {
    throw Error("fvvdp_heatmap_image: the map is " + std::to_string(distortion.width) + "x" +
                std::to_string(distortion.height) + ", the reference " +
                std::to_string(reference.width) + "x" + std::to_string(reference.height));
  }
  if (!(max_jod > 0.0)) throw Error("fvvdp_heatmap_image: max_jod must be > 0");
  Image out(reference.width, reference.height);
  for (size_t i = 0; i < distortion.values.size(); ++i) {
    const std::uint8_t* px = &reference.rgba[i * 4];
    // The reference as a dimmed grey, so that the colour carries the difference.
    const double grey = (0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2]) * 0.6;
    const double t = std::clamp(distortion.values[i] / max_jod, 0.0, 1.0);
    // Green (invisible) through yellow (half of max_jod) to red.
    const double r = t < 0.5 ? 2.0 * t : 1.0, g = t < 0.5 ? 1.0 : 2.0 * (1.0 - t);
    const double alpha = 0.3 + 0.6 * t;
    std::uint8_t* o = out.at(static_cast<int>(i % static_cast<size_t>(out.width)),
                             static_cast<int>(i / static_cast<size_t>(out.width)));
    o[0] = static_cast<std::uint8_t>(std::lround(grey * (1.0 - alpha) + 255.0 * r * alpha));
    o[1] = static_cast<std::uint8_t>(std::lround(grey * (1.0 - alpha) + 255.0 * g * alpha));
    o[2] = static_cast<std::uint8_t>(std::lround(grey * (1.0 - alpha)));
    o[3] = 255;
  }
  return out;
}

nlohmann::json to_json(const FvvdpResult& r) {
  const auto finite_or_null = [](double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  };
  nlohmann::json bands = nlohmann::json::array();
  for (const FvvdpBand& b : r.bands) {
    bands.push_back({{"from_deg", b.from_deg},
                     {"to_deg", finite_or_null(b.to_deg)},
                     {"jod", finite_or_null(b.jod)},
                     {"pixels_fraction", b.pixels_fraction}});
  }
  nlohmann::json frames = nlohmann::json::array();
  for (double v : r.frame_jod) frames.push_back(finite_or_null(v));
  return {{"metric", "FovVideoVDP v1.2 (parameters 1.2.3)"},
          {"jod", finite_or_null(r.jod)},
          {"frames", r.frames},
          {"image", r.image},
          {"fps", r.fps},
          {"foveated", r.foveated},
          {"pixels_per_degree", r.pixels_per_degree},
          {"photometry",
           {{"peak_cd_m2", r.photometry.peak_cd_m2},
            {"contrast_ratio", r.photometry.contrast_ratio},
            {"ambient_lux", r.photometry.ambient_lux},
            {"reflectivity", r.photometry.reflectivity},
            {"black_cd_m2", r.photometry.black_cd_m2()}}},
          {"bands", bands},
          {"frame_jod", frames}};
}

FvvdpResult fvvdp_image(const Image& test, const Image& reference, const Display& display,
                        Vec2d gaze_px, const FvvdpOptions& options) {
  Fvvdp m(display, options);
  m.add(test, reference, gaze_px);
  return m.result();
}

}  // namespace foveate::metrics
