// A multipass Shadertoy project: a JSON file naming the pass files (Common,
// Buffer A-D, Image) and what each pass's iChannels read, after the
// structure of Shadertoy's own export ("renderpass": a list of passes with a
// name, code and inputs) with files instead of inline code, and the same
// "iChannelN" keys as a single shader's channels JSON:
//
//   {"passes": [
//     {"name": "Common", "file": "common.glsl"},
//     {"name": "Buffer A", "file": "a.glsl", "iChannel0": "Buffer A"},
//     {"name": "Image", "file": "image.glsl", "iChannel0": "Buffer A",
//      "iChannel1": "noise.png"}]}
//
// A channel names a buffer ("Buffer A".."Buffer D") or an image file
// (relative to the JSON file).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "factories.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/json_read.hpp"
#include "shadertoy_scene.hpp"

namespace foveate::detail {

namespace {

namespace fs = std::filesystem;

const char* const kChannels[] = {"iChannel0", "iChannel1", "iChannel2", "iChannel3"};
const char* const kBuffers[] = {"Buffer A", "Buffer B", "Buffer C", "Buffer D"};

int buffer_id(const std::string& name) {
  for (int i = 0; i < 4; ++i) {
    if (name == kBuffers[i]) return i;
  }
  return -1;
}

// The list of passes of a project file.
const nlohmann::json& project_passes(const nlohmann::json& j, const std::string& path,
                                     const SceneOptions& o) {
  if (!j.is_object()) throw Error(path + ": a Shadertoy project is a JSON object with \"passes\"");
  if (!o.channels.empty()) {
    throw Error(path +
                ": --channel is for a single shader; a project binds its channels in its passes");
  }
  JsonReader top(j, path);
  const nlohmann::json* passes = top.get("passes");
  if (!passes) {
    throw Error(path +
                ": not a Shadertoy project: no \"passes\" (a list of {\"name\", \"file\", "
                "\"iChannel0\"..})");
  }
  if (!passes->is_array() || passes->empty())
    throw Error(path + ": passes: expected a non-empty list of passes");
  top.finish();
  return *passes;
}

// A project's passes as they are read: the channel values are resolved once
// every buffer is known.
class ProjectReader {
 public:
  ProjectReader(const std::string& path, ShadertoyProject& p)
      : dir_(fs::path(path).parent_path()), p_(p), key_("project:" + fs::absolute(path).string()) {}

  // Pass `k` of the list (`where` names it in errors).
  void read_pass(const nlohmann::json& pj, const std::string& where) {
    if (!pj.is_object()) throw Error(where + ": expected an object {\"name\", \"file\", ...}");
    JsonReader r(pj, where);
    std::string name, file;
    if (!r.string("name", name))
      throw Error(where + ": missing \"name\" (Common, Buffer A-D or Image)");
    if (!r.string("file", file)) throw Error(where + ": missing \"file\" (the pass's GLSL)");
    const std::string file_path = (dir_ / file).string();
    const int id = buffer_id(name);
    if (name != "Common" && name != "Image" && id < 0) {
      throw Error(r.path("name") + ": '" + name +
                  "' is not a Shadertoy pass (Common, Buffer A, Buffer B, Buffer C, Buffer D, "
                  "Image)");
    }
    const bool dup = name == "Common"  ? p_.common.has_value()
                     : name == "Image" ? have_image_
                                       : seen_[id];
    if (dup) throw Error(r.path("name") + ": a second '" + name + "' pass");
    if (name == "Common") {
      for (const char* c : kChannels) {
        if (r.get(c)) throw Error(r.path(c) + ": the Common part has no channels");
      }
      r.finish();
      p_.common = read_user_pass(file_path, "Common", false);
      key_ += "|" + std::to_string(std::hash<std::string>{}(p_.common->text));
      return;
    }
    ShadertoyPass pass;
    pass.name = name;
    pass.code = read_user_pass(file_path, name + " pass", true);
    key_ += "|" + name + ":" + std::to_string(std::hash<std::string>{}(pass.code.text));
    for (size_t c = 0; c < 4; ++c) {
      std::string v;
      if (r.string(kChannels[c], v)) pending_.push_back({id, c, v, r.path(kChannels[c])});
    }
    if (name == "Image") {
      have_image_ = true;
      p_.image = std::move(pass);
    } else {
      seen_[id] = true;
      buffers_[id] = std::move(pass);
    }
    r.finish();
  }

  // The buffers in Shadertoy's order (A, B, C, D, then Image) and every
  // channel bound; the project's key.
  void finish(const std::string& path) {
    if (!have_image_) throw Error(path + ": passes: no \"Image\" pass (the one shown)");
    for (int i = 0; i < 4; ++i) {
      if (buffers_[i]) p_.buffers.emplace_back(i, std::move(*buffers_[i]));
    }
    for (const Pending& q : pending_) bind(q);
    p_.key = key_;
  }

 private:
  struct Pending {
    int owner;  // -1 = Image, else the buffer
    size_t channel;
    std::string value;
    std::string where;
  };

  // The buffers this project has, for errors.
  [[nodiscard]] std::string buffer_list() const {
    std::string s;
    for (int i = 0; i < 4; ++i) {
      if (seen_[i]) s += std::string(s.empty() ? "" : ", ") + kBuffers[i];
    }
    return s.empty() ? std::string("no buffers") : s;
  }

  void bind(const Pending& q) {
    ShadertoyPass* pass = &p_.image;
    for (auto& entry : p_.buffers) {
      if (entry.first == q.owner) pass = &entry.second;
    }
    if (q.value.empty()) return;
    const int b = buffer_id(q.value);
    if (b >= 0) {
      if (!seen_[b]) {
        throw Error(q.where + ": '" + q.value + "' is not a pass of this project (it has " +
                    buffer_list() + ")");
      }
      pass->channels[q.channel].buffer = b;
    } else if (q.value.rfind("Buffer ", 0) == 0) {
      throw Error(q.where + ": '" + q.value + "': buffers are Buffer A, B, C and D");
    } else {
      p_.images.push_back(read_channel_image((dir_ / q.value).string(), q.where));
      pass->channels[q.channel].image = static_cast<int>(p_.images.size()) - 1;
    }
  }

  fs::path dir_;
  ShadertoyProject& p_;
  std::string key_;
  bool have_image_ = false;
  bool seen_[4] = {};
  std::vector<Pending> pending_;
  std::optional<ShadertoyPass> buffers_[4];
};

}  // namespace

std::unique_ptr<Scene> make_shadertoy_project(const std::string& path, const SceneOptions& o) {
  require_regular_file(path, "Shadertoy project");
  const nlohmann::json j = read_json_file(path);
  const nlohmann::json& passes = project_passes(j, path, o);
  ShadertoyProject p;
  p.scene_name = fs::path(path).filename().string();
  p.description = "Shadertoy project " + path;
  p.camera = o.camera_path.empty() ? CameraPath::orbit({0, 0, 0}, 5, 1, 30)
                                   : CameraPath::load(o.camera_path);
  p.date = o.date;
  ProjectReader reader(path, p);
  for (size_t k = 0; k < passes.size(); ++k) {
    reader.read_pass(passes[k], path + ": passes[" + std::to_string(k) + "]");
  }
  reader.finish(path);
  require_camera_read(p, o.camera_path);
  return make_shadertoy_scene(std::move(p));
}

}  // namespace foveate::detail
