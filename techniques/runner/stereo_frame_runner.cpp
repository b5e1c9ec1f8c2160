#include "foveate/techniques/stereo_frame_runner.hpp"

#include <string>

#include "foveate/core/error.hpp"
#include "foveate/gpu/frame.hpp"

namespace foveate {

std::array<GazeState, 2> eye_gaze_states(const StereoDisplay& display, const GazeState& cyclopean,
                                         double vergence_m) {
  const StereoGaze g = stereo_gaze(display, cyclopean.gaze_px, vergence_m);
  std::array<GazeState, 2> out{cyclopean, cyclopean};
  for (Eye e : kEyes) out[static_cast<size_t>(e)].gaze_px = g.eye(e);
  return out;
}

EyeView eye_view(const StereoDisplay& display, Eye eye) {
  return EyeView{display.eye_offset_m(eye), frustum_tangents(display.eye(eye))};
}

StereoFrameRunner::StereoFrameRunner(Scene& left, Scene& right, const StereoDisplay& display,
                                     const FrameRunnerOptions& options)
    : display_(display) {
  if (&left == &right) {
    throw Error(
        "stereo frame runner: each eye needs a scene instance of its own (a scene keeps one "
        "frame's camera and buffers)");
  }
  for (Eye e : kEyes) {
    const Display& d = display.eye(e);
    if (d.width_px != options.width || d.height_px != options.height) {
      throw Error("stereo frame runner: the " + std::string(eye_name(e)) + " eye's display is " +
                  std::to_string(d.width_px) + "x" + std::to_string(d.height_px) +
                  " but the eye's output size is " + std::to_string(options.width) + "x" +
                  std::to_string(options.height) + " (use Display::resized)");
    }
    FrameRunnerOptions o = options;
    o.eye = eye_view(display, e);
    eyes_[static_cast<size_t>(e)] = std::make_unique<FrameRunner>(e == Eye::Left ? left : right, o);
  }
  GLint max = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  if (2 * options.width > max) {
    throw Error("stereo output " + std::to_string(2 * options.width) + "x" +
                std::to_string(options.height) + ": larger than this GL's maximum texture size " +
                std::to_string(max));
  }
  output_ = gpu::RenderTarget::create(2 * options.width, options.height);
}

StereoFrameRunner::~StereoFrameRunner() = default;

std::array<FrameStats, 2> StereoFrameRunner::render(Technique& left, Technique& right, int frame,
                                                    const std::array<GazeState, 2>& gaze) {
  return render(left, right, eyes_[0]->frame_input(frame), gaze);
}

std::array<FrameStats, 2> StereoFrameRunner::render(Technique& left, Technique& right,
                                                    const FrameInput& input,
                                                    const std::array<GazeState, 2>& gaze) {
  if (&left == &right) {
    throw Error(
        "stereo frame runner: each eye needs a technique instance of its own (history, "
        "jitter and masks are per eye)");
  }
  std::array<FrameStats, 2> stats;
  for (Eye e : kEyes) {
    const size_t i = static_cast<size_t>(e);
    Technique& t = e == Eye::Left ? left : right;
    const Vec2d want = display_.eye(e).principal_point(), have = t.display().principal_point();
    if (want.x != have.x || want.y != have.y) {
      throw Error("stereo frame runner: technique " + t.name() + " given for the " + eye_name(e) +
                  " eye is configured for another view (principal point " + std::to_string(have.x) +
                  ", " + std::to_string(have.y) + " instead of " + std::to_string(want.x) + ", " +
                  std::to_string(want.y) + ")");
    }
    FrameInput in = input;
    in.eye = eyes_[i]->options().eye;
    stats[i] = eyes_[i]->render(t, in, gaze[i]);
    const gpu::RenderTarget& src = eyes_[i]->output();
    glCopyImageSubData(src.color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, output_.color().id(),
                       GL_TEXTURE_2D, 0, static_cast<GLint>(i) * src.width(), 0, 0, src.width(),
                       src.height(), 1);
  }
  return stats;
}

Image StereoFrameRunner::read_output() const { return gpu::read_texture(output_.color()); }

Image StereoFrameRunner::read_eye(Eye e) const {
  return eyes_[static_cast<size_t>(e)]->read_output();
}

void StereoFrameRunner::set_overlay(bool on) {
  for (auto& r : eyes_) r->set_overlay(on);
}

}  // namespace foveate
