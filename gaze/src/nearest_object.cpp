#include "foveate/gaze/nearest_object.hpp"

namespace foveate::gaze {

namespace {

Vec2d lerp(Vec2d a, Vec2d b, double u) { return {a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)}; }

}  // namespace

NearestObjectViewer::NearestObjectViewer(const Display& display,
                                         std::function<std::vector<Vec2d>(double)> objects,
                                         MainSequence main_sequence, double catch_up_deg)
    : display_(display),
      objects_(std::move(objects)),
      ms_(main_sequence),
      catch_up_deg_(catch_up_deg) {}

GazeSample NearestObjectViewer::sample(double t_s) {
  const std::vector<Vec2d> objs = objects_ ? objects_(t_s) : std::vector<Vec2d>{};
  if (!started_) {
    pos_ = objs.empty() ? Vec2d{0.5, 0.5} : objs.front();
    started_ = true;
  }
  if (in_saccade_) {
    const double u = (t_s - sac_start_) / sac_dur_;
    if (u < 1.0) {
      pos_ = lerp(sac_from_, sac_to_, profile_position(u, sac_a_));
      return {t_s, pos_, 1.0, true};
    }
    in_saccade_ = false;
    pos_ = sac_to_;
  }
  if (!objs.empty()) {
    const Vec2d target = objs.front();
    const double amp = angle_between_deg(display_, pos_, target);
    if (amp > catch_up_deg_) {
      // A new or escaped object: saccade to where it is now; pursuit resumes after landing.
      in_saccade_ = true;
      sac_start_ = t_s;
      sac_from_ = pos_;
      sac_to_ = target;
      sac_dur_ = ms_.duration_s(amp);
      sac_a_ = profile_exponent_for_ratio(ms_.peak_velocity_deg_per_s(amp) * sac_dur_ / amp);
    } else {
      pos_ = target;  // smooth pursuit
    }
  }
  return {t_s, pos_, 1.0, true};
}

std::string NearestObjectViewer::describe() const { return "looking at the nearest scene object"; }

}  // namespace foveate::gaze
