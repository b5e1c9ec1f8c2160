#pragma once
// A viewer that looks at the nearest scene object, for scenes that report
// their objects' positions.
#include <functional>
#include <string>
#include <vector>

#include "foveate/gaze/gaze.hpp"
#include "foveate/gaze/main_sequence.hpp"

namespace foveate::gaze {

/// Looks at the nearest scene object (ctx.objects()[0]): a main-sequence
/// saccade when it changes or escapes by more than `catch_up_deg`, smooth
/// pursuit otherwise; the screen centre while there is no object.
class NearestObjectViewer final : public GazeSource {
 public:
  NearestObjectViewer(const Display& display, std::function<std::vector<Vec2d>(double)> objects,
                      MainSequence main_sequence = {}, double catch_up_deg = 1.0);
  GazeSample sample(double t_s) override;
  [[nodiscard]] std::string describe() const override;

 private:
  Display display_;
  std::function<std::vector<Vec2d>(double)> objects_;
  MainSequence ms_;
  double catch_up_deg_;
  Vec2d pos_{0.5, 0.5};
  bool started_ = false;
  bool in_saccade_ = false;
  double sac_start_ = 0, sac_dur_ = 0, sac_a_ = 2;
  Vec2d sac_from_{}, sac_to_{};
};

}  // namespace foveate::gaze
