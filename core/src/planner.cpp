#include "foveate/core/planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>

#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"

namespace foveate {

namespace {
constexpr double kRad = std::numbers::pi / 180.0;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Continuous geometry of one plan, shared by the optimiser and the report.
struct Geometry {
  double focal = 0.0;  // V* D* / W* in pixels
  double long_axis = 0.0;
  double aspect = 1.0;
  double sharp = 0.0;   // w*
  double e_star = 0.0;  // e*
};

// Eq. 3 and 4 for an inner layer: a square of diameter 2 f tan(e) / s.
double inner_pixels(const Geometry& g, double e, double s) {
  const double d = 2.0 * g.focal * std::tan(e * kRad) / s;
  return d * d;
}

// Eq. 3 and 4 for the outer layer: the whole screen at sampling factor s.
double outer_pixels(const Geometry& g, double s) {
  const double d = g.long_axis / s;
  return g.aspect * d * d;
}

}  // namespace

double sampling_factor_at(double e, const AcuityModel& a, const Display& d) {
  return std::max(1.0, a.mar_deg(e) / d.sharpness_deg());
}

namespace {

// The sampling factor of a layer over the eccentricities [a, b): the
// acuity's at a (1 for the first) and, through a lens (lens.hpp), no finer
// than the panel shows anywhere in that ring, whose view angles from the lens
// axis (gamma being the gaze's) are at least 0 when it holds the axis,
// gamma - b inside it, a - gamma outside it.
class LayerSampling {
 public:
  LayerSampling(const Display& display, const AcuityModel& acuity, const PlannerOptions& opt)
      : display_(display), acuity_(acuity), table_(display.lens_oversampling_table()) {
    if (table_ && opt.gaze) {
      if (!std::isfinite(opt.gaze->x) || !std::isfinite(opt.gaze->y)) {
        throw Error("gaze: must be finite");
      }
      gamma_ = display.eccentricity_deg(display.principal_point(), *opt.gaze);
      any_gaze_ = false;
    }
  }
  /// The acuity's factor at eccentricity e.
  [[nodiscard]] double after(double e) const { return sampling_factor_at(e, acuity_, display_); }
  /// The lens's factor over [a, b).
  [[nodiscard]] double lens(double a, double b) const {
    if (!table_) return 1.0;
    double from = 0.0;  // any gaze: the whole buffer
    if (!any_gaze_) from = gamma_ < a ? a - gamma_ : (gamma_ > b ? gamma_ - b : 0.0);
    // Less than 5 % of oversampling is not worth a resampled layer: it would
    // save under 10 % of the layer's pixels and cost the fovea its exactness
    // (a layer at s > 1 is jittered and resolved, not native).
    const double s = table_->least_beyond(from).least();
    return s < 1.05 ? 1.0 : s;
  }
  /// Both.
  [[nodiscard]] double layer(double a, double b) const {
    return std::max(a > 0.0 ? after(a) : 1.0, lens(a, b));
  }

 private:
  const Display& display_;
  const AcuityModel& acuity_;
  std::optional<OversamplingTable> table_;
  double gamma_ = 0.0;
  bool any_gaze_ = true;
};

// Each layer's weight, checked along with the rest of the options.
std::vector<double> checked_weights(const Display& display, const AcuityModel& acuity,
                                    const PlannerOptions& opt) {
  display.validate();
  const int n = opt.layers;
  if (n < 1 || n > 6) throw Error("layers: expected 1..6, got " + std::to_string(n));
  if (!(opt.grid_step_deg > 0.0) || opt.grid_step_deg > 1.0) {
    throw Error("grid step: expected (0, 1] degrees, got " + format_number(opt.grid_step_deg));
  }
  if (!(acuity.slope > 0.0) || !std::isfinite(acuity.slope)) {
    throw Error("slope: must be a positive number, got " + format_number(acuity.slope));
  }
  std::vector<double> w = opt.weights;
  if (w.empty()) w.assign(n, 1.0);
  if (static_cast<int>(w.size()) != n) {
    throw Error("weights: expected " + std::to_string(n) + " values, got " +
                std::to_string(w.size()));
  }
  for (double x : w) {
    if (!(x > 0.0) || !std::isfinite(x)) throw Error("weights: each must be > 0");
  }
  return w;
}

// Candidate radii: the grid strictly inside (0, e*), bounded in number.
std::vector<double> candidate_radii(const Geometry& g, const PlannerOptions& opt) {
  const double points = std::floor(g.e_star / opt.grid_step_deg);
  if (!(points <= static_cast<double>(opt.max_grid_points))) {
    // The smallest step within the limit, rounded up to two significant digits.
    const double least = g.e_star / opt.max_grid_points;
    const double unit = std::pow(10.0, std::floor(std::log10(least)) - 1.0);
    char msg[400];
    std::snprintf(msg, sizeof msg,
                  "--step %g deg: %.0f candidate radii up to e* = %.2f deg, over the limit of "
                  "%d (the search grows with their square); use a step of at least %.2g deg, or "
                  "raise the limit (foveate plan --max-grid)",
                  opt.grid_step_deg, points, g.e_star, opt.max_grid_points,
                  std::ceil(least / unit) * unit);
    throw Error(msg);
  }
  std::vector<double> grid;
  for (int k = 1;; ++k) {
    const double e = k * opt.grid_step_deg;
    if (e >= g.e_star) break;
    grid.push_back(e);
  }
  return grid;
}

// The candidates for e_1: the grid, or the one radius a fixed s2 gives.
std::vector<double> first_radii(const Geometry& g, const std::vector<double>& grid,
                                const AcuityModel& acuity, const PlannerOptions& opt) {
  if (!opt.fixed_s2) return grid;
  if (opt.layers < 2) throw Error("fixed s2: needs at least 2 layers");
  const double s2 = *opt.fixed_s2;
  if (!(s2 >= 1.0)) throw Error("fixed s2: must be >= 1");
  const double e1 = acuity.eccentricity_for_mar(s2 * g.sharp);
  if (!(e1 > 0.0 && e1 < g.e_star)) {
    throw Error("fixed s2: s2 = " + format_number(s2) + " puts e1 outside the display");
  }
  return {e1};
}

// e_1 .. e_{n-1} with the least weighted pixels in total (dynamic
// programming over the candidates: cost[i][k] is the least of layers 1..i+1
// with e_{i+1} = cand[i][k]).
std::vector<double> optimal_radii(const Geometry& g, const std::vector<double>& grid,
                                  const std::vector<double>& w, const LayerSampling& sampling,
                                  const AcuityModel& acuity, const PlannerOptions& opt) {
  const int n = opt.layers;
  const int m = n - 1;
  std::vector<std::vector<double>> cand(m, grid);
  cand[0] = first_radii(g, grid, acuity, opt);
  std::vector<std::vector<double>> cost(m);
  std::vector<std::vector<int>> from(m);
  cost[0].resize(cand[0].size());
  for (size_t k = 0; k < cand[0].size(); ++k)
    cost[0][k] = w[0] * inner_pixels(g, cand[0][k], sampling.layer(0.0, cand[0][k]));
  for (int i = 1; i < m; ++i) {
    cost[i].assign(cand[i].size(), kInf);
    from[i].assign(cand[i].size(), -1);
    for (size_t j = 0; j < cand[i - 1].size(); ++j) {
      if (!std::isfinite(cost[i - 1][j])) continue;
      const double s0 = sampling.after(cand[i - 1][j]);
      for (size_t k = 0; k < cand[i].size(); ++k) {
        if (cand[i][k] <= cand[i - 1][j]) continue;
        const double s = std::max(s0, sampling.lens(cand[i - 1][j], cand[i][k]));
        const double c = cost[i - 1][j] + w[i] * inner_pixels(g, cand[i][k], s);
        if (c < cost[i][k]) {
          cost[i][k] = c;
          from[i][k] = static_cast<int>(j);
        }
      }
    }
  }
  double best = kInf;
  int arg = -1;
  for (size_t j = 0; j < cand[m - 1].size(); ++j) {
    if (!std::isfinite(cost[m - 1][j])) continue;
    const double c =
        cost[m - 1][j] + w[n - 1] * outer_pixels(g, sampling.layer(cand[m - 1][j], kInf));
    if (c < best) {
      best = c;
      arg = static_cast<int>(j);
    }
  }
  if (arg < 0) return {};  // no room: plan_layers says so, naming the display
  std::vector<double> radii(m, 0.0);
  for (int i = m - 1; i >= 0; --i) {
    radii[i] = cand[i][arg];
    if (i > 0) arg = from[i][arg];
  }
  return radii;
}

// The plan of layers with radii e_1 .. e_{n-1}.
LayerPlan make_plan(const Display& display, const AcuityModel& acuity, const Geometry& g,
                    const std::vector<double>& radii, const LayerSampling& sampling) {
  const int n = static_cast<int>(radii.size()) + 1;
  LayerPlan plan;
  plan.display = display;
  plan.acuity = acuity;
  plan.native_pixels = static_cast<double>(display.width_px) * display.height_px;
  for (int i = 0; i < n; ++i) {
    Layer L;
    const double inner = i > 0 ? radii[i - 1] : 0.0;
    const double s = sampling.layer(inner, i < n - 1 ? radii[i] : kInf);
    L.sampling_factor = s;
    if (i < n - 1) {
      L.radius_deg = radii[i];
      L.radius_px = g.focal * std::tan(radii[i] * kRad);
      const int d = std::max(1, static_cast<int>(std::lround(2.0 * L.radius_px / s)));
      L.width_px = L.height_px = d;
    } else {
      L.radius_deg = g.e_star;
      L.radius_px = g.focal * std::tan(g.e_star * kRad);
      L.width_px = std::max(1, static_cast<int>(std::lround(display.width_px / s)));
      L.height_px = std::max(1, static_cast<int>(std::lround(display.height_px / s)));
    }
    L.pixels = static_cast<double>(L.width_px) * L.height_px;
    plan.total_pixels += L.pixels;
    plan.total_pixels_half_rate += i == 0 ? L.pixels : 0.5 * L.pixels;
    plan.layers.push_back(L);
  }
  if (n == 1) plan.total_pixels_half_rate = plan.total_pixels;
  return plan;
}

}  // namespace

LayerPlan plan_layers(const Display& display, const AcuityModel& acuity,
                      const PlannerOptions& opt) {
  const std::vector<double> w = checked_weights(display, acuity, opt);
  Geometry g;
  g.focal = display.eye_distance_px();
  g.long_axis = display.long_axis_px();
  g.aspect = display.aspect();
  g.sharp = display.sharpness_deg();
  g.e_star = display.half_fov_deg();
  const LayerSampling sampling(display, acuity, opt);
  const std::vector<double> grid = candidate_radii(g, opt);
  const std::vector<double> radii =
      opt.layers > 1 ? optimal_radii(g, grid, w, sampling, acuity, opt) : std::vector<double>{};
  if (opt.layers > 1 && radii.empty()) {
    // The display is named by its file when it came from one: that is what
    // the user has to change.
    const std::string which = display.source.empty() ? "'" + display.name + "'" : display.source;
    throw Error("layers: the display " + which + " (" + std::to_string(display.width_px) + "x" +
                std::to_string(display.height_px) + " px, " + format_fixed(2 * g.e_star, 1) +
                " deg across) is too small for " + std::to_string(opt.layers) +
                " layers at a grid step of " + format_number(opt.grid_step_deg) +
                " deg: give it a wider field of view or plan fewer layers");
  }
  return make_plan(display, acuity, g, radii, sampling);
}

void to_json(nlohmann::json& j, const LayerPlan& p) {
  nlohmann::json disp = p.display;
  disp["half_fov_deg"] = p.display.half_fov_deg();
  disp["sharpness_deg"] = p.display.sharpness_deg();
  disp["eye_distance_px"] = p.display.eye_distance_px();
  nlohmann::json layers = nlohmann::json::array();
  for (const Layer& L : p.layers) {
    layers.push_back({{"radius_deg", L.radius_deg},
                      {"radius_px", L.radius_px},
                      {"sampling_factor", L.sampling_factor},
                      {"width_px", L.width_px},
                      {"height_px", L.height_px},
                      {"pixels", L.pixels}});
  }
  j = nlohmann::json{{"display", disp},
                     {"acuity", {{"slope", p.acuity.slope}, {"w0_deg", p.acuity.w0_deg}}},
                     {"layers", layers},
                     {"native_pixels", p.native_pixels},
                     {"total_pixels", p.total_pixels},
                     {"total_pixels_half_rate", p.total_pixels_half_rate},
                     {"pixel_ratio", p.pixel_ratio()},
                     {"pixel_ratio_half_rate", p.pixel_ratio_half_rate()}};
}

const std::vector<SweepVariant>& sweep_variants() {
  static const std::vector<SweepVariant> v = {
      {"2", 2, std::nullopt}, {"3", 3, std::nullopt}, {"4", 4, std::nullopt}, {"3*", 3, 2.0}};
  return v;
}

std::vector<SweepRow> fov_sweep(double from, double to, double step, double grid_step,
                                int max_grid_points) {
  if (!(from > 0.0) || !(to < 179.0) || !(from <= to) || !(step > 0.0)) {
    throw Error("sweep: need 0 < from <= to < 179 and step > 0");
  }
  std::vector<SweepRow> rows;
  const AcuityModel qa = AcuityModel::preset("A"), qb = AcuityModel::preset("B");
  for (double fov = from; fov <= to + 1e-9; fov += step) {
    SweepRow row;
    row.fov_deg = fov;
    // Eq. 9: D*(theta*) = 4 tan(theta*/2) / tan(w0); aspect 3/4, w* = w0.
    row.display_width_px = 4.0 * std::tan(0.5 * fov * kRad) / std::tan(kFovealMarDeg * kRad);
    Display d;
    d.name = "sweep";
    d.fov_h_deg = fov;
    d.width_px = static_cast<int>(std::lround(row.display_width_px));
    d.height_px = static_cast<int>(std::lround(0.75 * row.display_width_px));
    row.native_pixels = static_cast<double>(d.width_px) * d.height_px;
    for (const SweepVariant& v : sweep_variants()) {
      PlannerOptions o;
      o.layers = v.layers;
      o.fixed_s2 = v.fixed_s2;
      o.grid_step_deg = grid_step;
      o.max_grid_points = max_grid_points;
      const LayerPlan pa = plan_layers(d, qa, o), pb = plan_layers(d, qb, o);
      row.speedup_a.push_back(pa.pixel_ratio());
      row.speedup_b.push_back(pb.pixel_ratio());
      row.pixels_a.push_back(pa.total_pixels);
      row.pixels_b.push_back(pb.total_pixels);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace foveate
