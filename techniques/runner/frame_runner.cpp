#include "foveate/techniques/frame_runner.hpp"

#include <string>

#include "foveate/core/error.hpp"
#include "foveate/gpu/frame.hpp"

namespace foveate {

namespace {

gpu::RenderTarget make_output(const FrameRunnerOptions& o) {
  if (o.width < 1 || o.height < 1) {
    throw Error("frame runner: output size " + std::to_string(o.width) + "x" +
                std::to_string(o.height) + " is empty");
  }
  GLint max = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  if (o.width > max || o.height > max) {
    throw Error("output size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                ": larger than this GL's maximum texture size " + std::to_string(max));
  }
  return gpu::RenderTarget::create(o.width, o.height);
}

}  // namespace

FrameRunner::FrameRunner(Scene& scene, const FrameRunnerOptions& options)
    : FrameRunner(scene, options, make_output(options)) {}

FrameRunner::FrameRunner(Scene& scene, const FrameRunnerOptions& options, gpu::RenderTarget target)
    : scene_(scene), options_(options), target_(std::move(target)) {
  if (target_.width() != options_.width || target_.height() != options_.height) {
    throw Error("frame runner: the target is " + std::to_string(target_.width()) + "x" +
                std::to_string(target_.height()) + " but the output size is " +
                std::to_string(options_.width) + "x" + std::to_string(options_.height));
  }
  if (!(options_.fps > 0.0)) throw Error("frame runner: the frame rate must be positive");
  if (!target_.srgb()) {
    throw Error(
        "frame runner: the target must be sRGB-encoded (GL_SRGB8_ALPHA8, or an sRGB-capable window "
        "framebuffer): techniques filter and blend in linear light and write linear values");
  }
}

FrameRunner::~FrameRunner() = default;

FrameInput FrameRunner::frame_input(int frame) const {
  FrameInput f;
  f.frame = frame;
  f.delta_s = 1.0 / options_.fps;
  f.time_s = options_.start_time_s + frame / options_.fps;
  f.width = options_.width;
  f.height = options_.height;
  f.mouse_px = options_.mouse_px;
  f.mouse_down = options_.mouse_down;
  f.eye = options_.eye;
  return f;
}

FrameStats FrameRunner::render(Technique& technique, int frame, const GazeState& gaze) {
  return render(technique, frame_input(frame), gaze);
}

FrameStats FrameRunner::render(Technique& technique, const FrameInput& input,
                               const GazeState& gaze) {
  if (input.width != target_.width() || input.height != target_.height()) {
    throw Error("frame runner: frame input is " + std::to_string(input.width) + "x" +
                std::to_string(input.height) + " but the target is " +
                std::to_string(target_.width()) + "x" + std::to_string(target_.height()));
  }
  check_scene(technique_info(technique.name()), scene_.info());
  const Display& d = technique.display();
  if (d.width_px != target_.width() || d.height_px != target_.height()) {
    throw Error("technique " + technique.name() + " is configured for a " +
                std::to_string(d.width_px) + "x" + std::to_string(d.height_px) +
                " display but the target is " + std::to_string(target_.width()) + "x" +
                std::to_string(target_.height()) + " (use Display::resized)");
  }
  scene_.update(input);
  FrameStats s = technique.render(scene_, input, gaze, target_);
  if (options_.overlay) {
    if (!overlay_) overlay_ = std::make_unique<OverlayPass>();
    overlay_->draw(technique.overlay(gaze), target_);
  }
  return s;
}

Image FrameRunner::read_output() const {
  if (target_.color()) return gpu::read_texture(target_.color());
  return gpu::read_framebuffer(target_.framebuffer(), target_.width(), target_.height());
}

}  // namespace foveate
