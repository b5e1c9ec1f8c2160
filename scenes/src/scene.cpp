#include "foveate/scenes/scene.hpp"

#include <algorithm>
#include <filesystem>

#include "factories.hpp"
#include "foveate/core/error.hpp"
#include "foveate/core/parse.hpp"
#include "foveate_embedded/scenes_shaders.hpp"
#include "scene_warnings.hpp"

namespace foveate {

std::span<const embedded::EmbeddedFile> scene_shader_files() { return embedded::scenes_shaders(); }

std::uint64_t hash_bytes(std::uint64_t hash, const void* bytes, std::size_t size) {
  const auto* b = static_cast<const unsigned char*>(bytes);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ b[i]) * 1099511628211ull;
  return hash;
}

void Scene::prepass(const View& view) {
  prepass_begin(view);
  prepass_draw(view, -1);
  prepass_end();
}
void Scene::prepass_begin(const View&) {}
void Scene::prepass_draw(const View&, int) {}
void Scene::prepass_end() {}

std::unique_ptr<Scene> load_scene(const std::string& name_or_path, const SceneOptions& options) {
  const detail::ScopedSceneWarnings warnings(options.warning);
  if (name_or_path == "guenter") return detail::make_guenter_scene(options);
  if (detail::is_builtin_shader_scene(name_or_path)) {
    return detail::make_builtin_shader_scene(name_or_path, options);
  }
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(name_or_path, ec)) {
    std::string names;
    std::vector<std::string> list;
    for (const auto& s : builtin_scenes()) {
      names += (names.empty() ? "" : ", ") + s.name;
      list.push_back(s.name);
    }
    throw Error("scene '" + name_or_path + "': not a built-in scene (" + names +
                ") nor an existing file" + did_you_mean(name_or_path, list));
  }
  std::string ext = fs::path(name_or_path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".glsl" || ext == ".frag" || ext == ".fs")
    return detail::make_shadertoy_file(name_or_path, options);
  if (ext == ".json") return detail::make_shadertoy_project(name_or_path, options);
  // Everything else goes to assimp, which names what it cannot read.
  return detail::make_mesh_file(name_or_path, options);
}

}  // namespace foveate
