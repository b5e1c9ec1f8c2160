#include "model_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "foveate/core/error.hpp"

namespace foveate::detail {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string human_bytes(std::uint64_t b) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double v = static_cast<double>(b);
  int u = 0;
  while (v >= 1024.0 && u < 6) v /= 1024.0, ++u;
  std::ostringstream s;
  s.precision(u == 0 ? 0 : 1);
  s << std::fixed << v << " " << units[u];
  return s.str();
}

std::uint64_t saturating_mul(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > UINT64_MAX / a) return UINT64_MAX;
  return a * b;
}
std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
  return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}

// Assimp's structures plus ours (GPU copy, LODs) per declared element:
// positions, normals, UVs and index lists, allocated several times over
// the post-processing steps.
constexpr std::uint64_t kBytesPerVertex = 160;
constexpr std::uint64_t kBytesPerFace = 96;
constexpr std::uint64_t kBytesPerAccessorElement = 64;
// Formats whose counts are not read here: the import holds several copies
// of the data, which is seldom more than this many times the file's size.
constexpr std::uint64_t kFileSizeFactor = 12;

std::string read_prefix(const std::string& path, size_t max) {
  std::ifstream in(path, std::ios::binary);
  std::string s(max, '\0');
  in.read(s.data(), static_cast<std::streamsize>(max));
  s.resize(static_cast<size_t>(std::max<std::streamsize>(0, in.gcount())));
  return s;
}

bool parse_count(const std::string& word, std::uint64_t& out) {
  if (word.empty() || word.size() > 19) return false;
  for (char c : word)
    if (c < '0' || c > '9') return false;
  out = std::stoull(word);
  return true;
}

// PLY: "element vertex N" / "element face M" lines up to end_header.
std::optional<std::uint64_t> ply_estimate(const std::string& path, std::string& why) {
  const std::string head = read_prefix(path, 64 * 1024);
  if (head.rfind("ply", 0) != 0) return std::nullopt;
  std::istringstream in(head);
  std::string line;
  std::uint64_t vertices = 0, faces = 0, total = 0;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string a, b, c;
    words >> a >> b >> c;
    if (a == "end_header") break;
    std::uint64_t n = 0;
    if (a != "element" || !parse_count(c, n)) continue;
    if (b == "vertex")
      vertices = saturating_add(vertices, n);
    else if (b == "face" || b == "tristrips")
      faces = saturating_add(faces, n);
    total =
        saturating_add(total, saturating_mul(n, b == "vertex" ? kBytesPerVertex : kBytesPerFace));
  }
  why = "its header declares " + std::to_string(vertices) + " vertices and " +
        std::to_string(faces) + " faces";
  return total;
}

// Binary STL: the facet count after the 80-byte header.
std::optional<std::uint64_t> stl_estimate(const std::string& path, std::uint64_t size,
                                          std::string& why) {
  const std::string head = read_prefix(path, 84);
  if (head.size() < 84 || lower(head.substr(0, 5)) == "solid") return std::nullopt;
  std::uint32_t n = 0;
  std::memcpy(&n, head.data() + 80, 4);            // little-endian on the machines we build for
  if (84 + 50ull * n > size) return std::nullopt;  // assimp refuses it early and cheaply
  why = "its header declares " + std::to_string(n) + " triangles";
  return saturating_mul(n, 3 * kBytesPerVertex + kBytesPerFace);
}

std::optional<std::uint64_t> gltf_json_estimate(const std::string& text, std::string& why) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::nullopt;  // the importer says why
  const auto it = j.find("accessors");
  if (it == j.end() || !it->is_array()) return std::nullopt;
  std::uint64_t elements = 0;
  for (const auto& a : *it) {
    if (!a.is_object()) continue;
    const auto c = a.find("count");
    if (c != a.end() && c->is_number_unsigned())
      elements = saturating_add(elements, c->get<std::uint64_t>());
  }
  why = "its accessors declare " + std::to_string(elements) + " elements";
  return saturating_mul(elements, kBytesPerAccessorElement);
}

std::optional<std::uint64_t> gltf_estimate(const std::string& path, const std::string& ext,
                                           std::uint64_t size, std::string& why) {
  if (ext == ".gltf") {
    if (size > (256u << 20)) return std::nullopt;  // data URIs: the size bound applies
    return gltf_json_estimate(read_prefix(path, static_cast<size_t>(size)), why);
  }
  // GLB: magic, version, length, then the JSON chunk's length and type.
  const std::string head = read_prefix(path, 20);
  if (head.size() < 20 || head.compare(0, 4, "glTF") != 0) return std::nullopt;
  std::uint32_t json_len = 0;
  std::memcpy(&json_len, head.data() + 12, 4);
  if (json_len > size - 20 || json_len > (256u << 20)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  in.seekg(20);
  std::string text(json_len, '\0');
  in.read(text.data(), json_len);
  if (static_cast<std::uint32_t>(in.gcount()) != json_len) return std::nullopt;
  return gltf_json_estimate(text, why);
}

}  // namespace

void check_model_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    throw Error(path + ": cannot read the model file: " + std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) throw Error(path + ": is a directory, not a model file");
  if (!S_ISREG(st.st_mode)) {
    const char* kind = S_ISFIFO(st.st_mode)                         ? "a named pipe (FIFO)"
                       : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                       : S_ISSOCK(st.st_mode)                       ? "a socket"
                                                                    : "not a regular file";
    throw Error(path + ": is " + std::string(kind) + ", not a model file (give a regular file)");
  }
  if (st.st_size == 0) throw Error(path + ": the model file is empty (0 bytes)");
  if (::access(path.c_str(), R_OK) != 0) {
    throw Error(path + ": cannot read the model file: " + std::strerror(errno));
  }
}

std::uint64_t default_model_memory_budget() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 4ull << 30;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) / 2;
}

std::uint64_t estimate_model_memory(const std::string& path, std::string& why) {
  std::error_code ec;
  const std::uint64_t size = fs::file_size(path, ec);
  if (ec) return 0;
  const std::string ext = lower(fs::path(path).extension().string());
  std::optional<std::uint64_t> est;
  if (ext == ".ply") est = ply_estimate(path, why);
  if (ext == ".stl") est = stl_estimate(path, size, why);
  if (ext == ".gltf" || ext == ".glb") est = gltf_estimate(path, ext, size, why);
  const std::uint64_t by_size = saturating_mul(size, kFileSizeFactor);
  if (est) return std::max(*est, by_size);
  why = "its size is " + human_bytes(size) + " (about " + std::to_string(kFileSizeFactor) +
        " times that while importing)";
  return by_size;
}

void check_model_memory(const std::string& path, std::uint64_t budget) {
  if (budget == 0) budget = default_model_memory_budget();
  std::string why;
  const std::uint64_t need = estimate_model_memory(path, why);
  if (need <= budget) return;
  throw Error(path + ": the model would need about " + human_bytes(need) + " to import (" + why +
              "), more than the budget of " + human_bytes(budget) +
              " (--model-memory-limit; the default is half the machine's memory)");
}

std::string trim_texture_name(const std::string& name) {
  const auto b = name.find_first_not_of(" \t\r\n\"");
  if (b == std::string::npos) return {};
  const auto e = name.find_last_not_of(" \t\r\n\"");
  return name.substr(b, e - b + 1);
}

namespace {

bool regular(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

// Case-insensitive search for `file` (lower case) under `root`, breadth
// first, at most `depth` folders down and `budget` entries in all.
std::optional<fs::path> search_tree(const fs::path& root, const std::string& file, int depth,
                                    int& budget) {
  std::vector<fs::path> level{root};
  for (int d = 0; d <= depth && !level.empty(); ++d) {
    std::vector<fs::path> next;
    for (const fs::path& dir : level) {
      std::error_code ec;
      fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
      if (ec) continue;
      std::vector<fs::path> subdirs;
      for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (ec || --budget < 0) break;
        const fs::path p = it->path();
        std::error_code e2;
        if (it->is_regular_file(e2) && lower(p.filename().string()) == file) return p;
        if (it->is_directory(e2) && !it->is_symlink(e2)) subdirs.push_back(p);
      }
      if (budget < 0) return std::nullopt;
      std::sort(subdirs.begin(), subdirs.end());
      next.insert(next.end(), subdirs.begin(), subdirs.end());
    }
    level = std::move(next);
  }
  return std::nullopt;
}

}  // namespace

std::optional<fs::path> find_texture(const fs::path& model_dir, const std::string& raw,
                                     std::string& tried) {
  std::string name = trim_texture_name(raw);
  if (name.rfind("file://", 0) == 0) name = name.substr(7);
  std::replace(name.begin(), name.end(), '\\', '/');
  // Blender: '//' is relative to the .blend file's folder.
  if (name.rfind("//", 0) == 0) name = name.substr(2);
  const fs::path dir = model_dir.empty() ? fs::path(".") : model_dir;
  const bool drive =
      name.size() >= 2 && std::isalpha(static_cast<unsigned char>(name[0])) && name[1] == ':';
  tried.clear();
  if (!drive) {
    const fs::path as_written = fs::path(name).is_absolute() ? fs::path(name) : dir / name;
    if (regular(as_written)) return as_written;
    tried = as_written.string();
  }
  std::string file = name.substr(drive ? 2 : 0);
  const auto slash = file.find_last_of('/');
  if (slash != std::string::npos) file = file.substr(slash + 1);
  if (file.empty() || file == "." || file == "..") return std::nullopt;
  const std::string key = lower(file);
  int budget = 20000;
  if (auto p = search_tree(dir, key, 4, budget)) return p;
  std::error_code ec;
  fs::path full = fs::weakly_canonical(fs::absolute(dir, ec), ec);
  if (!full.has_filename()) full = full.parent_path();  // a trailing separator
  const fs::path parent = full.parent_path();
  std::string where = "'" + file + "' in any letter case under " + dir.string() + " (4 levels)";
  if (!ec && !parent.empty() && parent != full) {
    int more = 20000;
    if (auto p = search_tree(parent, key, 2, more)) return p;
    where += " and " + parent.string() + " (2 levels)";
  }
  tried += (tried.empty() ? "" : ", then ") + where;
  return std::nullopt;
}

}  // namespace foveate::detail
