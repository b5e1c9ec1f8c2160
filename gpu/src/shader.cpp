#include "foveate/gpu/shader.hpp"

#include <cstring>
#include <regex>
#include <sstream>

#include "foveate/core/error.hpp"
#include "foveate_embedded/gpu_shaders.hpp"

namespace foveate::gpu {

GLint Program::uniform_if_present(const char* name) const {
  auto it = locations_.find(std::string_view(name));
  if (it != locations_.end()) return it->second;
  const GLint loc = glGetUniformLocation(id(), name);
  locations_.emplace(name, loc);
  return loc;
}

void Program::allow_missing(std::initializer_list<const char*> names) const {
  for (const char* n : names) (void)uniform_if_present(n);
}

GLint Program::uniform(const char* name) const {
  const bool known = locations_.find(std::string_view(name)) != locations_.end();
  const GLint loc = uniform_if_present(name);
  if (loc < 0 && !known) {
    // Only reaches anyone where KHR_debug output is on (debug contexts).
    const std::string msg = "program '" + label_ + "' has no active uniform '" + name + "'";
    glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_ERROR, 1,
                         GL_DEBUG_SEVERITY_HIGH, -1, msg.c_str());
  }
  return loc;
}

void Program::set(const char* n, float v) const { glProgramUniform1f(id(), uniform(n), v); }
void Program::set(const char* n, int v) const { glProgramUniform1i(id(), uniform(n), v); }
void Program::set(const char* n, float x, float y) const {
  glProgramUniform2f(id(), uniform(n), x, y);
}
void Program::set(const char* n, float x, float y, float z) const {
  glProgramUniform3f(id(), uniform(n), x, y, z);
}
void Program::set(const char* n, float x, float y, float z, float w) const {
  glProgramUniform4f(id(), uniform(n), x, y, z, w);
}
void Program::set_mat4(const char* n, const float* m) const {
  glProgramUniformMatrix4fv(id(), uniform(n), 1, GL_FALSE, m);
}
void Program::set_mat3(const char* n, const float* m) const {
  glProgramUniformMatrix3fv(id(), uniform(n), 1, GL_FALSE, m);
}

ShaderCompiler::ShaderCompiler(std::vector<std::span<const embedded::EmbeddedFile>> tables)
    : tables_(std::move(tables)) {
  tables_.push_back(embedded::gpu_shaders());
}

std::string_view ShaderCompiler::file(std::string_view name) const {
  for (const auto& t : tables_) {
    for (const auto& f : t) {
      if (f.name == name) return f.text;
    }
  }
  throw Error("shader file '" + std::string(name) + "' is not embedded in this build");
}

namespace {

// Expands `#include "name"` recursively, numbering each file as a GLSL source
// string so that the driver's messages can be mapped back.
class Assembler {
 public:
  Assembler(const ShaderCompiler& c, std::vector<std::string>& names) : c_(c), names_(names) {}

  void add(const std::string& name, std::string_view text, int depth = 0) {
    if (depth > 16) throw Error(name + ": #include nested too deeply (a cycle?)");
    const int index = static_cast<int>(names_.size());
    names_.push_back(name);
    out_ << "#line 1 " << index << '\n';
    std::istringstream in{std::string(text)};
    std::string line;
    int number = 0;
    static const std::regex include_re(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    static const std::regex version_re(R"(^\s*#\s*version\b.*$)");
    std::smatch m;
    while (std::getline(in, line)) {
      ++number;
      if (std::regex_match(line, m, include_re)) {
        add(m[1].str(), c_.file(m[1].str()), depth + 1);
        out_ << "#line " << number + 1 << ' ' << index << '\n';
      } else if (std::regex_match(line, version_re)) {
        out_ << "\n";  // the compiler supplies #version 450 core
      } else {
        out_ << line << '\n';
      }
    }
  }
  std::string str() const { return out_.str(); }

 private:
  const ShaderCompiler& c_;
  std::vector<std::string>& names_;
  std::ostringstream out_;
};

const char* stage_name(GLenum s) {
  switch (s) {
    case GL_VERTEX_SHADER:
      return "vertex";
    case GL_FRAGMENT_SHADER:
      return "fragment";
    case GL_COMPUTE_SHADER:
      return "compute";
    case GL_GEOMETRY_SHADER:
      return "geometry";
    default:
      return "shader";
  }
}

}  // namespace

std::string map_info_log(const std::string& log, const std::vector<std::string>& names) {
  static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
  static const std::regex nvidia(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
  std::istringstream in(log);
  std::ostringstream out;
  std::string line;
  std::smatch m;
  auto name = [&](const std::string& idx) {
    const size_t i = std::stoul(idx);
    return i < names.size() ? names[i] : "source " + idx;
  };
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (std::regex_match(line, m, mesa)) {
      out << name(m[1]) << ':' << m[2] << ':' << m[3] << ": " << m[4] << '\n';
    } else if (std::regex_match(line, m, nvidia)) {
      out << name(m[1]) << ':' << m[2] << ": " << m[3] << '\n';
    } else {
      out << line << '\n';
    }
  }
  return out.str();
}

Program ShaderCompiler::build(const std::vector<StageSource>& stages,
                              const std::string& what) const {
  std::vector<Handle<detail::delete_shader>> shaders;
  GLuint program = glCreateProgram();
  Program p(program, what);
  for (const StageSource& st : stages) {
    std::vector<std::string> names;
    Assembler a(*this, names);
    for (const auto& piece : st.pieces) {
      a.add(piece.name, piece.text.empty() ? file(piece.name) : std::string_view(piece.text));
    }
    const std::string src = "#version 450 core\n" + a.str();
    Handle<detail::delete_shader> sh(glCreateShader(st.stage));
    const char* ptr = src.c_str();
    glShaderSource(sh.id(), 1, &ptr, nullptr);
    glCompileShader(sh.id());
    GLint ok = 0;
    glGetShaderiv(sh.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      GLint len = 0;
      glGetShaderiv(sh.id(), GL_INFO_LOG_LENGTH, &len);
      std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
      glGetShaderInfoLog(sh.id(), len, nullptr, log.data());
      log.resize(std::strlen(log.c_str()));
      throw Error(what + ": " + stage_name(st.stage) + " shader does not compile:\n" +
                  map_info_log(log, names));
    }
    glAttachShader(program, sh.id());
    shaders.push_back(std::move(sh));
  }
  glLinkProgram(program);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(program, len, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    throw Error(what + ": program does not link:\n" + log);
  }
  for (auto& s : shaders) glDetachShader(program, s.id());
  return p;
}

Program ShaderCompiler::build(const std::string& vertex, const std::string& fragment) const {
  return build({StageSource{GL_VERTEX_SHADER, {{vertex, {}}}},
                StageSource{GL_FRAGMENT_SHADER, {{fragment, {}}}}},
               vertex + " + " + fragment);
}

}  // namespace foveate::gpu
