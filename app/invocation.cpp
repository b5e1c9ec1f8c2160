#include "invocation.hpp"

namespace foveate::app {

namespace {

std::string& invocation_storage() {
  static std::string s;
  return s;
}

}  // namespace

std::string shell_quote(const std::string& a) {
  if (!a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789-_./=:,+@%") == std::string::npos)
    return a;
  std::string q = "'";
  for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void set_invocation(int argc, const char* const* argv) {
  std::string s = "foveate";  // argv[0] is wherever the binary was
  for (int i = 1; i < argc; ++i) s += " " + shell_quote(argv[i]);
  invocation_storage() = s;
}

const std::string& invocation() { return invocation_storage(); }

}  // namespace foveate::app
