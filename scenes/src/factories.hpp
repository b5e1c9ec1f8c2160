#pragma once
// Constructors of the concrete scenes, used by load_scene().
#include <memory>
#include <string>

#include "foveate/scenes/scene.hpp"

namespace foveate::detail {

/// A Shadertoy-style shader: a user file, or a built-in by name.
std::unique_ptr<Scene> make_shadertoy_file(const std::string& path, const SceneOptions& options);
std::unique_ptr<Scene> make_builtin_shader_scene(const std::string& name,
                                                 const SceneOptions& options);
bool is_builtin_shader_scene(const std::string& name);
/// A multipass Shadertoy project (JSON naming the pass files and channels).
std::unique_ptr<Scene> make_shadertoy_project(const std::string& path, const SceneOptions& options);
/// A mesh file through assimp; the test scene of Guenter et al.
std::unique_ptr<Scene> make_mesh_file(const std::string& path, const SceneOptions& options);
std::unique_ptr<Scene> make_guenter_scene(const SceneOptions& options);

}  // namespace foveate::detail
