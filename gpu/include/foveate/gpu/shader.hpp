#pragma once
// GLSL programs from sources embedded at build time. Sources may
// `#include "name"` other embedded files; the compiler inserts #line
// directives so that compile errors are reported against the original file
// and line ("scenes/shaders/terrain.frag:42: error: ..."). User files (e.g. a
// Shadertoy shader) are added by path and reported the same way.
#include <initializer_list>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "foveate/gpu/embedded.hpp"
#include "foveate/gpu/gl.hpp"

namespace foveate::gpu {

class Program : public Handle<detail::delete_program> {
 public:
  Program() = default;
  explicit Program(GLuint id, std::string label = {}) : Handle(id), label_(std::move(label)) {}
  /// Uniform location by name (cached). A name the program does not have
  /// (misspelled, or optimised away) gives -1 and, under a debug context, a
  /// GL debug error naming the program and the uniform: tests fail on it.
  GLint uniform(const char* name) const;
  /// The same without the report.
  GLint uniform_if_present(const char* name) const;
  /// Names the program may lack without a report (inputs a user's shader may
  /// ignore, like Shadertoy's iDate): setting them is then a silent no-op.
  void allow_missing(std::initializer_list<const char*> names) const;
  /// What the program is, for messages ("layered/composite.frag").
  [[nodiscard]] const std::string& label() const { return label_; }
  void use() const { glUseProgram(id()); }
  void set(const char* name, float v) const;
  void set(const char* name, int v) const;
  void set(const char* name, int x, int y) const;
  void set(const char* name, float x, float y) const;
  void set(const char* name, float x, float y, float z) const;
  void set(const char* name, float x, float y, float z, float w) const;
  void set_mat4(const char* name, const float* m) const;
  void set_mat3(const char* name, const float* m) const;

 private:
  std::string label_;
  mutable std::map<std::string, GLint, std::less<>> locations_;
};

/// One stage's source, named for error messages.
struct StageSource {
  GLenum stage = GL_FRAGMENT_SHADER;
  /// Pieces concatenated in order; each is an embedded file name, or literal
  /// text when `literal` is set (named `label` in errors).
  struct Piece {
    std::string name;
    std::string text;  ///< used when non-empty (generated or user text); `name` labels it
  };
  std::vector<Piece> pieces;
};

class ShaderCompiler {
 public:
  /// The tables of embedded files that names and #includes resolve against;
  /// gpu's own common snippets are always included.
  explicit ShaderCompiler(std::vector<std::span<const embedded::EmbeddedFile>> tables = {});
  /// Text of an embedded file; throws foveate::Error if unknown.
  [[nodiscard]] std::string_view file(std::string_view name) const;
  /// Compiles and links; throws foveate::Error whose message lists each error
  /// as "file:line: message".
  Program build(const std::vector<StageSource>& stages, const std::string& what) const;
  /// Shortcut: vertex + fragment from embedded file names.
  Program build(const std::string& vertex, const std::string& fragment) const;

 private:
  std::vector<std::span<const embedded::EmbeddedFile>> tables_;
};

/// Where the lines of an assembled stage came from: the source strings'
/// names, by index, and runs of consecutive lines of one file (a file is
/// split into several runs around its #includes).
struct SourceMap {
  struct Segment {
    int index = 0;       ///< into names
    int first_line = 0;  ///< line number the driver reports for the run's first line
    int file_line = 0;   ///< that line's number in the file
    int count = 0;       ///< lines in the run
  };
  std::vector<std::string> names;
  std::vector<Segment> segments;
};

/// Maps a driver info log (Mesa "0:12(3): error: ..." or NVIDIA "0(12) : error ...")
/// to "file:line: ...": by the segment that holds the reported line where
/// there is one, else by the source number.
std::string map_info_log(const std::string& log, const SourceMap& map);
/// The same with source names only (each source string numbered from line 1).
std::string map_info_log(const std::string& log, const std::vector<std::string>& names);

}  // namespace foveate::gpu
