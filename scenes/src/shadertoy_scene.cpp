// Screen-space scenes: Shadertoy shaders (user files, unchanged; multipass
// projects) and the built-in procedural scenes written in the same form.
#include "shadertoy_scene.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "factories.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/json_read.hpp"
#include "foveate/gpu/frame.hpp"
#include "foveate/gpu/pass.hpp"
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
     "expensive ray-marched scene: soft shadows, occlusion, reflections (about 1 s per 1080p frame "
     "on llvmpipe: 988 ms in README.md's table)",
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

const char* const kChannelNames[] = {"iChannel0", "iChannel1", "iChannel2", "iChannel3"};

// The GLSL of one pass: prelude, Common, the pass's code, then `main_file`.
std::vector<gpu::StageSource::Piece> pass_pieces(const gpu::ShaderCompiler& c,
                                                 const std::optional<UserPass>& common,
                                                 const ShadertoyPass& pass) {
  std::vector<const UserPass*> parts;
  if (common) parts.push_back(&*common);
  parts.push_back(&pass.code);
  std::vector<gpu::StageSource::Piece> pieces = prelude_pieces(c, parts);
  if (common) pieces.push_back({common->path, common->text});
  pieces.push_back({pass.code.path, pass.code.text});
  return pieces;
}

class ShadertoyScene final : public Scene {
 public:
  explicit ShadertoyScene(ShadertoyProject p) : p_(std::move(p)) {
    const gpu::ShaderCompiler c({embedded::scenes_shaders()});
    pieces_ = pass_pieces(c, p_.common, p_.image);
    pieces_.push_back({"shadertoy_adapter.glsl", {}});
    // The user's macros end with the user's code: what a technique appends
    // (its main, gpu's colour helpers) must not be rewritten by them. But
    // FOVEATE_FOOTPRINT is the scene's word to the shading mains that it
    // reads foveate_footprint_px (scenes/shaders/footprint.glsl).
    std::string undef;
    for (const UserPass* part : {p_.common ? &*p_.common : nullptr, &p_.image.code}) {
      if (!part) continue;
      for (const std::string& m : part->source.macros) {
        // Reserved names cannot be undefined (nor defined: the compiler says so).
        if (m.rfind("GL_", 0) != 0 && m.find("__") == std::string::npos && m != "FOVEATE_FOOTPRINT")
          undef += "#undef " + m + "\n";
      }
    }
    if (!undef.empty()) pieces_.push_back({"shadertoy_undef.glsl (generated)", undef});
    // A shader that reads the clock, the frame number or the date changes
    // from frame to frame whatever the camera does; so does one with buffers.
    animated_ = p_.image.code.source.animated || !p_.buffers.empty() ||
                (p_.common && p_.common->source.animated);
    Image black(1, 1);
    black.rgba = {0, 0, 0, 255};
    black_ = gpu::upload_image(black);
    for (const Image& img : p_.images) textures_.push_back(gpu::upload_image(img));
    if (!p_.buffers.empty()) vao_ = gpu::VertexArray::create();
    for (const auto& [id, pass] : p_.buffers) {
      std::vector<gpu::StageSource::Piece> pieces = pass_pieces(c, p_.common, pass);
      pieces.push_back({"shadertoy_buffer.frag", {}});
      buffer_programs_.push_back(
          c.build({gpu::StageSource{GL_VERTEX_SHADER, {{"fullscreen.vert", {}}}},
                   gpu::StageSource{GL_FRAGMENT_SHADER, pieces}},
                  "scene '" + p_.scene_name + "', " + pass.name));
      allow_missing_shadertoy_inputs(buffer_programs_.back());
    }
  }

  SceneInfo info() const override { return {p_.scene_name, p_.description, false, false, 0}; }
  std::string shade_key() const override { return p_.key; }
  std::vector<gpu::StageSource::Piece> shade_source() const override { return pieces_; }

  void update(const FrameInput& f) override {
    frame_ = f;
    pose_ = p_.camera.at(f.time_s);
    if (!p_.buffers.empty()) run_buffers(f);
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
    allow_missing_shadertoy_inputs(p);
    p.allow_missing({"foveate_cam_pos", "foveate_cam_target", "foveate_cam_fov"});
    float size[4][2];
    bind_channels(p, p_.image, samplers, find_set(frame_.width, frame_.height), size);
    set_shadertoy_inputs(p, frame_, p_.date, size);
    const CameraPose& pose = pose_;
    p.set("foveate_cam_pos", float(pose.position.x), float(pose.position.y),
          float(pose.position.z));
    p.set("foveate_cam_target", float(pose.target.x), float(pose.target.y), float(pose.target.z));
    p.set("foveate_cam_fov", float(pose.fov_deg));
  }

 private:
  // Two float targets per buffer (the one read holds the last frame) at one
  // output size, and the last frame rendered into them.
  struct BufferSet {
    int width = 0, height = 0;
    int last_frame = -1;
    std::uint64_t used = 0;
    std::array<std::array<gpu::RenderTarget, 2>, 4> targets;
    std::array<int, 4> current{};  // which of the two holds the latest frame
  };

  BufferSet* find_set(int w, int h) {
    for (BufferSet& s : sets_) {
      if (s.width == w && s.height == h) return &s;
    }
    return nullptr;
  }

  // Renders Buffer A-D once per frame, in order, at the output size (each
  // size its own set: the supersampled reference renders at a larger one).
  // A frame number seen before does nothing; a smaller one starts over from
  // cleared buffers, so a run from frame 0 gives the same images every time.
  void run_buffers(const FrameInput& f) {
    BufferSet* set = find_set(f.width, f.height);
    if (!set) {
      if (sets_.size() >= 3) {
        auto oldest = std::min_element(
            sets_.begin(), sets_.end(),
            [](const BufferSet& a, const BufferSet& b) { return a.used < b.used; });
        sets_.erase(oldest);
      }
      sets_.emplace_back();
      set = &sets_.back();
      set->width = f.width;
      set->height = f.height;
      for (const auto& entry : p_.buffers) {
        for (auto& t : set->targets[static_cast<size_t>(entry.first)])
          t = gpu::RenderTarget::create(f.width, f.height, GL_RGBA32F);
      }
    }
    set->used = ++use_counter_;
    if (f.frame == set->last_frame) return;
    const gpu::FramebufferBinding saved = gpu::FramebufferBinding::current();
    if (f.frame < set->last_frame || set->last_frame < 0) {
      for (const auto& entry : p_.buffers) {
        for (auto& t : set->targets[static_cast<size_t>(entry.first)]) t.clear(0, 0, 0, 0);
      }
    }
    set->last_frame = f.frame;
    for (size_t k = 0; k < p_.buffers.size(); ++k) {
      const auto& [id, pass] = p_.buffers[k];
      const gpu::Program& prog = buffer_programs_[k];
      const size_t b = static_cast<size_t>(id);
      const gpu::RenderTarget& out = set->targets[b][1 - set->current[b]];
      gpu::Samplers samplers;
      float size[4][2];
      bind_channels(prog, pass, samplers, set, size);
      set_shadertoy_inputs(prog, f, p_.date, size);
      out.bind();
      gpu::apply(gpu::PassState{});
      prog.use();
      glBindVertexArray(vao_.id());
      glDrawArrays(GL_TRIANGLES, 0, 3);
      set->current[b] = 1 - set->current[b];
    }
    saved.restore();
  }

  void bind_channels(const gpu::Program& p, const ShadertoyPass& pass, gpu::Samplers& samplers,
                     const BufferSet* set, float size[4][2]) {
    for (size_t i = 0; i < 4; ++i) {
      const ChannelSource& src = pass.channels[i];
      if (src.buffer >= 0 && set) {
        const size_t b = static_cast<size_t>(src.buffer);
        samplers.bind(p, kChannelNames[i], set->targets[b][set->current[b]].color());
        size[i][0] = float(set->width);
        size[i][1] = float(set->height);
      } else if (src.image >= 0) {
        const size_t k = static_cast<size_t>(src.image);
        samplers.bind(p, kChannelNames[i], textures_[k]);
        size[i][0] = float(p_.images[k].width);
        size[i][1] = float(p_.images[k].height);
      } else {
        samplers.bind(p, kChannelNames[i], black_);
        size[i][0] = size[i][1] = 1.0f;
      }
    }
  }

  ShadertoyProject p_;
  std::vector<gpu::StageSource::Piece> pieces_;
  gpu::Texture black_;
  std::vector<gpu::Texture> textures_;
  std::vector<gpu::Program> buffer_programs_;
  gpu::VertexArray vao_;
  std::vector<BufferSet> sets_;
  std::uint64_t use_counter_ = 0;
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

void warn_unbound(const ShadertoyProject& p) {
  if (p.builtin) return;
  auto check = [](const ShadertoyPass& pass, const std::optional<UserPass>& common) {
    for (size_t i = 0; i < 4; ++i) {
      const bool sampled = pass.code.source.channels[i] || (common && common->source.channels[i]);
      const ChannelSource& s = pass.channels[i];
      if (sampled && s.image < 0 && s.buffer < 0) {
        warn_once(pass.code.path + ": samples " + kChannelNames[i] +
                  " but no image or buffer is bound to it; it reads black");
      }
    }
  };
  for (const auto& entry : p.buffers) check(entry.second, p.common);
  check(p.image, p.common);
}

// The channel images of a single shader: --channel files, or NAME.json
// beside it ({"iChannel0": "file.png", ...}).
void load_channels(const std::string& shader_path, const SceneOptions& o, ShadertoyProject& p) {
  std::vector<std::string> files = o.channels;
  if (files.size() > 4)
    throw Error("at most 4 channel images (iChannel0..3), got " + std::to_string(files.size()));
  if (!shader_path.empty() && files.empty()) {
    fs::path side = fs::path(shader_path).replace_extension(".json");
    std::error_code ec;
    if (fs::exists(side, ec)) {
      require_regular_file(side.string(), "channels file");
      const nlohmann::json j = read_json_file(side.string());
      JsonReader r(j, side.string());
      files.assign(4, "");
      for (int i = 0; i < 4; ++i) {
        std::string f;
        if (r.string(kChannelNames[i], f))
          files[static_cast<size_t>(i)] = (side.parent_path() / f).string();
      }
      r.finish();
    }
  }
  for (size_t i = 0; i < files.size(); ++i) {
    if (files[i].empty()) continue;
    p.images.push_back(read_channel_image(files[i], kChannelNames[i]));
    p.image.channels[i].image = static_cast<int>(p.images.size()) - 1;
  }
}

}  // namespace

void require_camera_read(const ShadertoyProject& project, const std::string& camera_path) {
  if (camera_path.empty()) return;
  const auto reads = [](const UserPass& u) {
    return u.text.find("foveate_cam_") != std::string::npos ||
           u.text.find("foveate_ray") != std::string::npos;
  };
  bool read = reads(project.image.code) || (project.common && reads(*project.common));
  for (const auto& [index, pass] : project.buffers) read = read || reads(pass.code);
  if (!read) {
    throw Error(camera_path + ": a camera path for scene '" + project.scene_name +
                "', whose shader reads no camera (foveate_cam_pos, foveate_cam_target or "
                "foveate_cam_fov): its frames would not follow the path; leave the camera path "
                "out, or read the camera in the shader (docs/shadertoy.md)");
  }
}

std::unique_ptr<Scene> make_shadertoy_scene(ShadertoyProject project) {
  warn_unbound(project);
  auto scene = std::make_unique<ShadertoyScene>(std::move(project));
  validate(*scene);
  return scene;
}

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
    ShadertoyProject p;
    p.scene_name = b.name;
    p.description = b.description;
    p.key = std::string("builtin:") + b.name;
    p.builtin = true;
    p.image.name = "Image";
    p.image.code.path = b.file;
    p.image.code.text = std::string(c.file(b.file));
    p.image.code.source = analyse_shadertoy_source(p.image.code.text);
    p.camera = o.camera_path.empty() ? b.camera() : CameraPath::load(o.camera_path);
    p.date = o.date;
    load_channels("", o, p);
    require_camera_read(p, o.camera_path);
    return make_shadertoy_scene(std::move(p));
  }
  throw Error("unknown built-in scene '" + name + "'");
}

std::unique_ptr<Scene> make_shadertoy_file(const std::string& path, const SceneOptions& o) {
  ShadertoyProject p;
  p.image.name = "Image";
  p.image.code = read_user_pass(path, "shader", true);
  p.scene_name = fs::path(path).filename().string();
  p.description = "Shadertoy shader " + path;
  p.key = "file:" + fs::absolute(path).string() + ":" +
          std::to_string(std::hash<std::string>{}(p.image.code.text));
  p.camera = o.camera_path.empty() ? CameraPath::orbit({0, 0, 0}, 5, 1, 30)
                                   : CameraPath::load(o.camera_path);
  p.date = o.date;
  load_channels(path, o, p);
  require_camera_read(p, o.camera_path);
  return make_shadertoy_scene(std::move(p));
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
