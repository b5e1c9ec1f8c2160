#include "foveate/gpu/shader.hpp"

#include <algorithm>
#include <cstring>
#include <string_view>

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
void Program::set(const char* n, int x, int y) const { glProgramUniform2i(id(), uniform(n), x, y); }
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

bool space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// `#` followed by `word` at the start of `line` (spaces allowed around the
// `#`); returns the position after the word, or npos. Linear, no regex: user
// text (a Shadertoy file) goes through here.
size_t directive(std::string_view line, std::string_view word) {
  size_t i = 0;
  while (i < line.size() && space(line[i])) ++i;
  if (i >= line.size() || line[i] != '#') return std::string_view::npos;
  ++i;
  while (i < line.size() && space(line[i])) ++i;
  if (line.substr(i, word.size()) != word) return std::string_view::npos;
  i += word.size();
  if (i < line.size() && !space(line[i]) && line[i] != '"') return std::string_view::npos;
  return i;
}

// `#include "name"` alone on its line: the name, or empty.
std::string include_name(std::string_view line) {
  size_t i = directive(line, "include");
  if (i == std::string_view::npos) return {};
  while (i < line.size() && space(line[i])) ++i;
  if (i >= line.size() || line[i] != '"') return {};
  const size_t close = line.find('"', i + 1);
  if (close == std::string_view::npos || close == i + 1) return {};
  for (size_t k = close + 1; k < line.size(); ++k) {
    if (!space(line[k])) return {};
  }
  return std::string(line.substr(i + 1, close - i - 1));
}

// Expands `#include "name"` (nested at most 16 deep), numbering each file as
// a GLSL source string, and gives every run of lines of one file a range of
// line numbers of its own (#line G index): drivers disagree on the source
// number they report (Mesa reports 0 for semantic errors), so the line alone
// finds the file and the line in it.
class Assembler {
 public:
  Assembler(const ShaderCompiler& c, SourceMap& map) : c_(c), map_(map) {}

  void add(const std::string& name, std::string_view text, int depth = 0) {
    if (depth > 16) throw Error(name + ": #include nested too deeply (a cycle?)");
    const int index = static_cast<int>(map_.names.size());
    map_.names.push_back(name);
    begin_segment(index, 1);
    int number = 0;
    size_t pos = 0;
    while (pos < text.size()) {
      size_t eol = text.find('\n', pos);
      if (eol == std::string_view::npos) eol = text.size();
      const std::string_view line = text.substr(pos, eol - pos);
      pos = eol + 1;
      ++number;
      const std::string inc = include_name(line);
      if (!inc.empty()) {
        add(inc, c_.file(inc), depth + 1);
        begin_segment(index, number + 1);
      } else if (directive(line, "version") != std::string_view::npos) {
        emit("");  // the compiler supplies #version 450 core
      } else {
        emit(line);
      }
    }
  }
  std::string str() const { return out_; }

 private:
  void begin_segment(int index, int file_line) {
    // A gap of one line between ranges keeps them apart even for messages
    // about the line after the last (unterminated constructs).
    next_line_ += 1;
    out_ += "#line " + std::to_string(next_line_) + ' ' + std::to_string(index) + '\n';
    map_.segments.push_back({index, next_line_, file_line, 0});
  }
  void emit(std::string_view line) {
    out_.append(line);
    out_ += '\n';
    ++map_.segments.back().count;
    ++next_line_;
  }

  const ShaderCompiler& c_;
  SourceMap& map_;
  std::string out_;
  int next_line_ = 0;
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

namespace {

// Reads digits at `i`; false if there are none (or too many to be a line).
bool read_int(std::string_view s, size_t& i, long& v) {
  const size_t start = i;
  v = 0;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9' && i - start < 10) v = v * 10 + (s[i++] - '0');
  return i > start && !(i < s.size() && s[i] >= '0' && s[i] <= '9');
}

// "S:L(C): msg" (Mesa) or "S(L) : msg" (NVIDIA), parsed by hand: driver logs
// quote user text, and a regex over a long line overflowed the stack.
bool parse_log_line(std::string_view line, long& src, long& ln, long& col, std::string_view& msg) {
  size_t i = 0;
  if (!read_int(line, i, src)) return false;
  col = -1;
  if (i < line.size() && line[i] == ':') {
    ++i;
    if (!read_int(line, i, ln) || i >= line.size() || line[i] != '(') return false;
    ++i;
    if (!read_int(line, i, col) || i + 1 >= line.size() || line[i] != ')' || line[i + 1] != ':')
      return false;
    i += 2;
  } else if (i < line.size() && line[i] == '(') {
    ++i;
    if (!read_int(line, i, ln) || i >= line.size() || line[i] != ')') return false;
    ++i;
    while (i < line.size() && space(line[i])) ++i;
    if (i >= line.size() || line[i] != ':') return false;
    ++i;
  } else {
    return false;
  }
  while (i < line.size() && space(line[i])) ++i;
  msg = line.substr(i);
  return true;
}

}  // namespace

std::string map_info_log(const std::string& log, const SourceMap& map) {
  std::string out;
  size_t pos = 0;
  while (pos < log.size()) {
    size_t eol = log.find('\n', pos);
    if (eol == std::string::npos) eol = log.size();
    const std::string_view line = std::string_view(log).substr(pos, eol - pos);
    pos = eol + 1;
    if (line.empty()) continue;
    long src = 0, ln = 0, col = -1;
    std::string_view msg;
    if (!parse_log_line(line, src, ln, col, msg)) {
      out.append(line);
      out += '\n';
      continue;
    }
    std::string name;
    long file_line = ln;
    // The segment holding the reported line, whatever the source number says.
    for (const SourceMap::Segment& s : map.segments) {
      if (ln >= s.first_line && ln < s.first_line + std::max(s.count, 1)) {
        name = map.names[static_cast<size_t>(s.index)];
        file_line = s.file_line + (ln - s.first_line);
        break;
      }
    }
    if (name.empty()) {
      name = src >= 0 && static_cast<size_t>(src) < map.names.size()
                 ? map.names[static_cast<size_t>(src)]
                 : "source " + std::to_string(src);
    }
    out += name + ':' + std::to_string(file_line);
    if (col >= 0) out += ':' + std::to_string(col);
    out += ": ";
    out.append(msg);
    out += '\n';
  }
  return out;
}

std::string map_info_log(const std::string& log, const std::vector<std::string>& names) {
  SourceMap map;
  map.names = names;
  return map_info_log(log, map);
}

Program ShaderCompiler::build(const std::vector<StageSource>& stages,
                              const std::string& what) const {
  std::vector<Handle<detail::delete_shader>> shaders;
  GLuint program = glCreateProgram();
  Program p(program, what);
  for (const StageSource& st : stages) {
    SourceMap names;
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
