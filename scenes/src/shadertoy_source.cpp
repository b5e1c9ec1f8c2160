// One linear pass over a Shadertoy shader's text: a tokenizer that skips
// comments and strings, and a few token-window checks on top of it. No
// regular expressions and no recursion, by design: std::regex recurses per
// character and overflows the stack on long inputs.
#include "foveate/scenes/shadertoy_source.hpp"

#include <algorithm>
#include <unordered_set>

namespace foveate {

namespace {

enum class Kind { identifier, number, punct };

struct Token {
  Kind kind = Kind::punct;
  std::string_view text;
  int line = 1;
  bool directive = false;           ///< on a preprocessor line
  bool first_on_directive = false;  ///< the `#` that starts a directive
};

bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }

// Produces tokens one at a time; every character is looked at a bounded
// number of times.
class Lexer {
 public:
  explicit Lexer(std::string_view s) : s_(s) {}

  bool next(Token& t) {
    skip_space_and_comments();
    if (i_ >= s_.size()) return false;
    t.line = line_;
    const char c = s_[i_];
    const size_t start = i_;
    t.first_on_directive = false;
    if (c == '#' && line_start_) {
      in_directive_ = true;
      t.first_on_directive = true;
    }
    line_start_ = false;
    t.directive = in_directive_;
    if (ident_start(c)) {
      while (i_ < s_.size() && ident_char(s_[i_])) ++i_;
      t.kind = Kind::identifier;
    } else if ((c >= '0' && c <= '9') ||
               (c == '.' && i_ + 1 < s_.size() && s_[i_ + 1] >= '0' && s_[i_ + 1] <= '9')) {
      while (i_ < s_.size() && (ident_char(s_[i_]) || s_[i_] == '.')) ++i_;
      t.kind = Kind::number;
    } else if (c == '"') {
      // A quoted string (#include "file"): up to the closing quote or the end
      // of the line, whichever comes first.
      ++i_;
      while (i_ < s_.size() && s_[i_] != '"' && s_[i_] != '\n') ++i_;
      if (i_ < s_.size() && s_[i_] == '"') ++i_;
      t.kind = Kind::punct;
    } else {
      ++i_;
      t.kind = Kind::punct;
    }
    t.text = s_.substr(start, i_ - start);
    return true;
  }

 private:
  void newline() {
    ++line_;
    line_start_ = true;
    in_directive_ = in_directive_ && continued_;
    continued_ = false;
  }
  void skip_space_and_comments() {
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '\n') {
        newline();
        ++i_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++i_;
      } else if (c == '\\' && i_ + 1 < s_.size() &&
                 (s_[i_ + 1] == '\n' ||
                  (s_[i_ + 1] == '\r' && i_ + 2 < s_.size() && s_[i_ + 2] == '\n'))) {
        // A line continuation keeps a directive going.
        continued_ = true;
        ++i_;
      } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
        while (i_ < s_.size() && s_[i_] != '\n') ++i_;
      } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
        i_ += 2;
        while (i_ < s_.size() && !(s_[i_] == '*' && i_ + 1 < s_.size() && s_[i_ + 1] == '/')) {
          if (s_[i_] == '\n') {
            ++line_;  // a block comment does not end a directive's line
          }
          ++i_;
        }
        i_ = std::min(s_.size(), i_ + 2);
      } else {
        return;
      }
    }
  }

  std::string_view s_;
  size_t i_ = 0;
  int line_ = 1;
  bool line_start_ = true;
  bool in_directive_ = false;
  bool continued_ = false;
};

bool is_qualifier(std::string_view w) {
  return w == "in" || w == "out" || w == "inout" || w == "const" || w == "highp" ||
         w == "mediump" || w == "lowp";
}

// Words after which a name is used, not declared.
bool is_statement_word(std::string_view w) {
  return w == "return" || w == "else" || w == "case" || w == "do" || w == "if" || w == "while" ||
         w == "for" || w == "switch" || w == "discard";
}

// Checks `([q] vec4 NAME, [q] vec2 NAME)` over the recorded parameter tokens.
bool main_image_params_match(const std::vector<std::string_view>& p) {
  size_t i = 0;
  auto param = [&](std::string_view type) {
    while (i < p.size() && is_qualifier(p[i])) ++i;
    if (i >= p.size() || p[i] != type) return false;
    ++i;
    if (i >= p.size() || !ident_start(p[i][0])) return false;
    ++i;
    return true;
  };
  if (!param("vec4")) return false;
  if (i >= p.size() || p[i] != ",") return false;
  ++i;
  if (!param("vec2")) return false;
  return i == p.size();
}

void add_once(std::vector<std::string>& v, std::string_view s) {
  if (std::find(v.begin(), v.end(), s) == v.end()) v.emplace_back(s);
}

// Records a macro name once; a set of the names seen keeps this linear.
class MacroSet {
 public:
  void add(std::vector<std::string>& out, std::string_view name) {
    if (seen_.insert(std::string(name)).second) out.emplace_back(name);
  }

 private:
  std::unordered_set<std::string> seen_;
};

}  // namespace

bool ShadertoySource::defines(std::string_view name) const {
  return std::find(user_defined.begin(), user_defined.end(), name) != user_defined.end();
}
bool ShadertoySource::uses_legacy(std::string_view name) const {
  return std::find(legacy_used.begin(), legacy_used.end(), name) != legacy_used.end();
}

namespace {

// The state of one pass over a shader: a small window of previous tokens
// (code only, not directives) and the state of the few constructs looked for.
class SourceAnalyser {
 public:
  explicit SourceAnalyser(ShadertoySource& r) : r_(r) {}

  void token(const Token& t) {
    const std::string_view w = t.text;
    const bool ident = t.kind == Kind::identifier;
    if (t.first_on_directive) {
      dir_index_ = 0;
      dir_define_ = false;
    } else if (t.directive) {
      ++dir_index_;
      if (dir_index_ == 1) dir_define_ = w == "define";
    }
    const bool after_define = t.directive && dir_define_ && dir_index_ == 2;
    if (after_define && ident) macro_set_.add(r_.macros, w);
    if (ident) name(t, after_define);
    if (t.directive) return;
    main_functions(t);
    if (depth_ == 0) uniform(w, ident);
    if (w == "{") ++depth_;
    if (w == "}" && depth_ > 0) --depth_;
    prev2_ = prev1_;
    prev1_ = w;
  }

  void finish() {
    for (size_t k = 0; k < kShadertoyLegacyNames.size(); ++k) {
      if (legacy_[k]) r_.legacy_used.emplace_back(kShadertoyLegacyNames[k]);
    }
  }

 private:
  // An identifier: channels, mainImage, animation inputs, legacy names.
  void name(const Token& t, bool after_define) {
    const std::string_view w = t.text;
    if (w.size() == 9 && w.substr(0, 8) == "iChannel" && w[8] >= '0' && w[8] <= '3') {
      r_.channels[static_cast<size_t>(w[8] - '0')] = true;
    }
    if (w == "mainImage") r_.mentions_main_image = true;
    if (w == "iTime" || w == "iGlobalTime" || w == "iTimeDelta" || w == "iFrame" || w == "iDate" ||
        w == "iChannelTime") {
      r_.animated = true;
    }
    for (size_t k = 0; k < kShadertoyLegacyNames.size(); ++k) {
      if (w == kShadertoyLegacyNames[k]) {
        legacy_[k] = true;
        const bool declared =
            after_define || (!t.directive && prev1_.size() > 0 && ident_start(prev1_[0]) &&
                             !is_statement_word(prev1_));
        if (declared) add_once(r_.user_defined, w);
      }
    }
  }

  // `void mainImage(...)` (its parameter list kept and checked) and `void main(`.
  void main_functions(const Token& t) {
    const std::string_view w = t.text;
    if (in_params_) {
      if (w == "(") ++paren_depth_;
      if (w == ")") {
        if (paren_depth_ == 0) {
          close_params();
        } else {
          --paren_depth_;
        }
      }
      if (in_params_ && params_.size() < 64) params_.push_back(w);
    } else if (depth_ == 0 && w == "(" && prev1_ == "mainImage" && prev2_ == "void" &&
               !r_.has_main_image) {
      in_params_ = true;
      paren_depth_ = 0;
      params_line_ = t.line;
      params_.clear();
    } else if (depth_ == 0 && w == "(" && prev1_ == "main" && prev2_ == "void" && !r_.has_main) {
      r_.has_main = true;
      r_.main_line = t.line;
    }
  }

  void close_params() {
    in_params_ = false;
    r_.has_main_image = true;
    r_.main_image_line = params_line_;
    r_.main_image_params_ok = main_image_params_match(params_);
    if (!r_.main_image_params_ok) {
      std::string joined;
      for (std::string_view p : params_) {
        if (!joined.empty() && p != "," && joined.back() != ',') joined += ' ';
        if (!joined.empty() && joined.back() == ',') joined += ' ';
        if (joined.size() + p.size() > 200) {
          joined += "...";
          break;
        }
        joined += p;
      }
      r_.main_image_params = joined;
    }
    params_.clear();
  }

  // Top-level uniforms: `uniform [qualifiers] TYPE NAME (, NAME)* ;`
  void uniform(std::string_view w, bool ident) {
    if (w == "uniform") {
      uniform_state_ = 1;
    } else if (uniform_state_ == 1 && ident && !is_qualifier(w)) {
      uniform_type_ = w;
      uniform_state_ = 2;
    } else if (uniform_state_ == 2 && ident) {
      r_.uniforms.push_back({std::string(uniform_type_), std::string(w)});
      uniform_state_ = 3;
    } else if (uniform_state_ == 3 && w == ",") {
      uniform_state_ = 2;
    } else if (uniform_state_ != 1 || !ident) {
      if (uniform_state_ == 3 && w == "[") {
        // an array: keep the declaration's name, skip its size
      } else if (w == ";" || uniform_state_ == 1 || uniform_state_ == 2) {
        uniform_state_ = 0;
      }
    }
  }

  ShadertoySource& r_;
  std::array<bool, kShadertoyLegacyNames.size()> legacy_{};
  MacroSet macro_set_;
  std::string_view prev1_, prev2_;  // the two code tokens before this one
  int dir_index_ = 0;               // position of a token on its directive's line
  bool dir_define_ = false;         // that directive is #define
  int depth_ = 0;                   // braces
  int paren_depth_ = 0;             // parentheses inside a mainImage parameter list
  bool in_params_ = false;
  int params_line_ = 0;
  std::vector<std::string_view> params_;
  // `uniform [precision] TYPE NAME`: 0 = none, 1 = after uniform, 2 = have type
  int uniform_state_ = 0;
  std::string_view uniform_type_;
};

}  // namespace

ShadertoySource analyse_shadertoy_source(std::string_view text) {
  ShadertoySource r;
  if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF &&
      static_cast<unsigned char>(text[1]) == 0xBB && static_cast<unsigned char>(text[2]) == 0xBF) {
    r.bom = true;
    text.remove_prefix(3);
  }
  SourceAnalyser analyser(r);
  Lexer lex(text);
  Token t;
  while (lex.next(t)) analyser.token(t);
  analyser.finish();
  return r;
}

}  // namespace foveate
