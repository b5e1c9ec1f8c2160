#pragma once
// The file side of model loading: what may be opened, how much memory the
// file declares, and where a material's texture file really is.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace foveate::detail {

/// Refuses, before anything opens it, a model path that is not a regular
/// non-empty file (a directory, FIFO, device or socket would block or fail
/// obscurely inside the importer).
void check_model_file(const std::string& path);

/// Half the machine's physical memory (sysconf), or 4 GiB when unknown.
std::uint64_t default_model_memory_budget();

/// Bytes the importer is expected to allocate for what `path` declares:
/// counts from the header of PLY, binary STL and glTF/GLB (accessor
/// counts), otherwise a bound from the file size. `why` says how it was
/// estimated.
std::uint64_t estimate_model_memory(const std::string& path, std::string& why);

/// Throws foveate::Error naming the file, the estimate and the option to
/// raise it when the estimate exceeds `budget` bytes (0 = the default).
void check_model_memory(const std::string& path, std::uint64_t budget);

/// Where the texture a material names lives, as users expect: backslashes
/// and drive letters (`C:\a\b.png`, `Q:/b.png`), `.\b.png`, Blender's `//`
/// prefix; first the path as written relative to the model's folder, then
/// the file name looked up case-insensitively in the model's folder tree and
/// its parent's (bounded depth and entries). Empty when not found; `tried`
/// says what was searched.
std::optional<std::filesystem::path> find_texture(const std::filesystem::path& model_dir,
                                                  const std::string& name, std::string& tried);

/// The name with surrounding blanks removed; empty means "no texture".
std::string trim_texture_name(const std::string& name);

}  // namespace foveate::detail
