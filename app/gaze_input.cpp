#include "gaze_input.hpp"

#include "cli_util.hpp"
#include "foveate/core/error.hpp"
#include "session.hpp"

namespace foveate::app {

namespace {

class FixedGaze final : public GazeInput {
 public:
  explicit FixedGaze(Vec2d p) : p_(p) {}
  GazeState at(double) override { return GazeState{p_}; }
  std::string describe() const override {
    return "fixed at (" + fmt(p_.x, 1) + ", " + fmt(p_.y, 1) + ") px";
  }

 private:
  Vec2d p_;
};

}  // namespace

std::unique_ptr<GazeInput> GazeInput::create(const std::string& spec, Session& session) {
  const int W = session.options().size.width, H = session.options().size.height;
  if (spec.empty()) return std::make_unique<FixedGaze>(Vec2d{0.5 * W, 0.5 * H});
  std::string s = spec;
  if (s.rfind("fixed:", 0) == 0) s = s.substr(6);
  return std::make_unique<FixedGaze>(parse_point(s, W, H, "--gaze"));
}

}  // namespace foveate::app
