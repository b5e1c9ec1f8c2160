// Screen-space scenes: Shadertoy shaders (user files, unchanged) and the
// built-in procedural scenes written in the same form.
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>

#include "factories.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/image.hpp"
#include "foveate/core/json_read.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/scenes/camera_path.hpp"
#include "foveate_embedded/scenes_shaders.hpp"

namespace foveate::detail {

namespace {

namespace fs = std::filesystem;

struct Builtin {
  const char* name;
  const char* file;
  const char* description;
  CameraPath (*camera)();
};

const Builtin kBuiltins[] = {
    {"raymarch", "raymarch.glsl",
     "expensive ray-marched scene: soft shadows, occlusion, reflections (about 2 s per 1080p frame "
     "on llvmpipe)",
     [] {
       return CameraPath::orbit({0.0, 1.0, 0.0}, 7.0, 1.8, 40.0, 55.0);
     }},
    {"detail", "detail.glsl",
     "fine high-contrast detail everywhere (checkers to the horizon, a zone plate): the aliasing "
     "worst case",
     [] {
       CameraPath p;
       p.loop = true;
       p.keys = {{0.0, {0, 1.6, 0}, {0, 1.0, -6}, 60.0},
                 {10.0, {4, 1.6, -8}, {3, 1.0, -14}, 60.0},
                 {20.0, {0, 1.6, -16}, {-2, 1.0, -22}, 60.0},
                 {30.0, {0, 1.6, 0}, {0, 1.0, -6}, 60.0}};
       return p;
     }},
    {"cheap", "cheap.glsl",
     "cheap smooth scene: a sky gradient and soft discs (a few ms per frame)",
     [] {
       return CameraPath::orbit({0.0, 0.0, 0.0}, 6.0, 2.5, 30.0, 55.0);
     }},
};

class ShadertoyScene final : public Scene {
 public:
  ShadertoyScene(std::string name, std::string description, std::string user_label,
                 std::string user_text, std::string key, CameraPath camera,
                 std::vector<Image> channels)
      : name_(std::move(name)),
        description_(std::move(description)),
        label_(std::move(user_label)),
        text_(std::move(user_text)),
        key_(std::move(key)),
        camera_(std::move(camera)) {
    // A shader that reads the clock, the frame number or the date changes
    // from frame to frame whatever the camera does.
    for (const char* input : {"iTime", "iGlobalTime", "iTimeDelta", "iFrame", "iDate"}) {
      animated_ = animated_ || text_.find(input) != std::string::npos;
    }
    // Unbound channels read black, as on shadertoy.com.
    Image black(1, 1);
    black.rgba = {0, 0, 0, 255};
    for (int i = 0; i < 4; ++i) {
      const Image& img =
          i < static_cast<int>(channels.size()) && !channels[i].empty() ? channels[i] : black;
      channel_size_[i][0] = static_cast<float>(img.width);
      channel_size_[i][1] = static_cast<float>(img.height);
      channels_[i] = gpu::upload_image(img);
    }
  }

  SceneInfo info() const override { return {name_, description_, false, false, 0}; }
  std::string shade_key() const override { return key_; }
  std::vector<gpu::StageSource::Piece> shade_source() const override {
    return {{"shadertoy_prelude.glsl", {}}, {label_, text_}, {"shadertoy_adapter.glsl", {}}};
  }

  void update(const FrameInput& f) override {
    frame_ = f;
    pose_ = camera_.at(f.time_s);
  }
  std::optional<std::uint64_t> image_key() const override {
    std::uint64_t h = 1469598103934665603ull;
    const double v[] = {pose_.position.x,
                        pose_.position.y,
                        pose_.position.z,
                        pose_.target.x,
                        pose_.target.y,
                        pose_.target.z,
                        pose_.fov_deg,
                        frame_.mouse_px.x,
                        frame_.mouse_px.y,
                        frame_.mouse_down ? 1.0 : 0.0,
                        double(frame_.width),
                        double(frame_.height),
                        animated_ ? frame_.time_s : 0.0,
                        animated_ ? double(frame_.frame) : 0.0};
    return hash_bytes(h, v, sizeof v);
  }

  void bind(const gpu::Program& p, const View&, gpu::Samplers& samplers) override {
    // A shader uses the inputs it needs; the rest are optimised away.
    p.allow_missing({"iResolution", "iTime", "iTimeDelta", "iFrameRate", "iFrame", "iMouse",
                     "iDate", "iSampleRate", "iChannel0", "iChannel1", "iChannel2", "iChannel3",
                     "iChannelResolution[0]", "iChannelResolution[1]", "iChannelResolution[2]",
                     "iChannelResolution[3]", "foveate_cam_pos", "foveate_cam_target",
                     "foveate_cam_fov"});
    const FrameInput& f = frame_;
    p.set("iResolution", float(f.width), float(f.height), 1.0f);
    p.set("iTime", float(f.time_s));
    p.set("iTimeDelta", float(f.delta_s));
    p.set("iFrameRate", float(f.delta_s > 0 ? 1.0 / f.delta_s : 60.0));
    p.set("iFrame", f.frame);
    // Shadertoy: xy = position while the button is down, zw = click position
    // (negative once released); pixels with the origin bottom-left.
    const float mx = float(f.mouse_px.x), my = float(f.height - f.mouse_px.y);
    p.set("iMouse", mx, my, f.mouse_down ? mx : -mx, -my);
    // A fixed date keeps runs deterministic: 2026-01-01, seconds = the clock.
    p.set("iDate", 2026.0f, 0.0f, 1.0f, float(f.time_s));
    p.set("iSampleRate", 44100.0f);
    const char* names[] = {"iChannel0", "iChannel1", "iChannel2", "iChannel3"};
    for (int i = 0; i < 4; ++i) samplers.bind(p, names[i], channels_[i]);
    glProgramUniform3f(p.id(), p.uniform("iChannelResolution[0]"), channel_size_[0][0],
                       channel_size_[0][1], 1.0f);
    glProgramUniform3f(p.id(), p.uniform("iChannelResolution[1]"), channel_size_[1][0],
                       channel_size_[1][1], 1.0f);
    glProgramUniform3f(p.id(), p.uniform("iChannelResolution[2]"), channel_size_[2][0],
                       channel_size_[2][1], 1.0f);
    glProgramUniform3f(p.id(), p.uniform("iChannelResolution[3]"), channel_size_[3][0],
                       channel_size_[3][1], 1.0f);
    const CameraPose& pose = pose_;
    p.set("foveate_cam_pos", float(pose.position.x), float(pose.position.y),
          float(pose.position.z));
    p.set("foveate_cam_target", float(pose.target.x), float(pose.target.y), float(pose.target.z));
    p.set("foveate_cam_fov", float(pose.fov_deg));
  }

 private:
  std::string name_, description_, label_, text_, key_;
  CameraPath camera_;
  gpu::Texture channels_[4];
  float channel_size_[4][2] = {};
  FrameInput frame_;
  CameraPose pose_{};
  bool animated_ = false;
};

// Compiles the scene's shading function alone so that errors surface at load.
void validate(const Scene& scene) {
  gpu::ShaderCompiler c({embedded::scenes_shaders()});
  std::vector<gpu::StageSource::Piece> pieces = scene.shade_source();
  pieces.push_back({"validate.frag", {}});
  c.build({gpu::StageSource{GL_VERTEX_SHADER, {{"fullscreen.vert", {}}}},
           gpu::StageSource{GL_FRAGMENT_SHADER, pieces}},
          "scene '" + scene.info().name + "'");
}

std::vector<Image> load_channels(const std::string& shader_path, const SceneOptions& o) {
  std::vector<std::string> files = o.channels;
  if (files.size() > 4)
    throw Error("at most 4 channel images (iChannel0..3), got " + std::to_string(files.size()));
  // A JSON file beside the shader: NAME.json with {"iChannel0": "file.png", ...}.
  if (!shader_path.empty() && files.empty()) {
    fs::path side = fs::path(shader_path).replace_extension(".json");
    std::error_code ec;
    if (fs::exists(side, ec)) {
      const nlohmann::json j = read_json_file(side.string());
      JsonReader r(j, side.string());
      files.assign(4, "");
      for (int i = 0; i < 4; ++i) {
        std::string f;
        const std::string key = "iChannel" + std::to_string(i);
        if (r.string(key.c_str(), f)) files[i] = (side.parent_path() / f).string();
      }
      r.finish();
    }
  }
  std::vector<Image> images;
  for (const std::string& f : files) images.push_back(f.empty() ? Image() : read_image(f));
  return images;
}

}  // namespace

bool is_builtin_shader_scene(const std::string& name) {
  for (const Builtin& b : kBuiltins) {
    if (name == b.name) return true;
  }
  return false;
}

std::unique_ptr<Scene> make_builtin_shader_scene(const std::string& name, const SceneOptions& o) {
  for (const Builtin& b : kBuiltins) {
    if (name != b.name) continue;
    gpu::ShaderCompiler c({embedded::scenes_shaders()});
    CameraPath cam = o.camera_path.empty() ? b.camera() : CameraPath::load(o.camera_path);
    auto scene = std::make_unique<ShadertoyScene>(
        b.name, b.description, b.file, std::string(c.file(b.file)),
        std::string("builtin:") + b.name, std::move(cam), load_channels("", o));
    validate(*scene);
    return scene;
  }
  throw Error("unknown built-in scene '" + name + "'");
}

std::unique_ptr<Scene> make_shadertoy_file(const std::string& path, const SceneOptions& o) {
  std::string text = read_file(path);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw Error(path + ": the shader file is empty");
  if (text.find('\0') != std::string::npos) throw Error(path + ": not a text file");
  static const std::regex main_image(
      R"(void\s+mainImage\s*\(\s*out\s+vec4\s+\w+\s*,\s*(in\s+)?vec2\s+\w+\s*\))");
  if (!std::regex_search(text, main_image)) {
    throw Error(path +
                ": no Shadertoy entry point: expected 'void mainImage(out vec4 fragColor, in vec2 "
                "fragCoord)'");
  }
  if (std::regex_search(text, std::regex(R"(\bvoid\s+main\s*\(\s*\))"))) {
    throw Error(path + ": defines main(); a Shadertoy shader defines only mainImage()");
  }
  CameraPath cam = o.camera_path.empty() ? CameraPath::orbit({0, 0, 0}, 5, 1, 30)
                                         : CameraPath::load(o.camera_path);
  const std::string stem = fs::path(path).filename().string();
  auto scene = std::make_unique<ShadertoyScene>(
      stem, "Shadertoy shader " + path, path, text,
      "file:" + fs::absolute(path).string() + ":" + std::to_string(std::hash<std::string>{}(text)),
      std::move(cam), load_channels(path, o));
  validate(*scene);
  return scene;
}

}  // namespace foveate::detail

namespace foveate {

std::vector<SceneListing> builtin_scenes() {
  std::vector<SceneListing> out;
  for (const auto& b : detail::kBuiltins) out.push_back({b.name, b.description});
  out.push_back(
      {"guenter",
       "the test scene of Guenter et al.: terrain, 20x20 parametric objects, procedural materials, "
       "environment map, continuous LOD (meshes: every technique incl. lodmask)"});
  return out;
}

}  // namespace foveate
