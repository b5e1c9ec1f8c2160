#pragma once
// The command line this process was started with, shell-quoted, recorded in
// the results of the runs it makes (results.json's "command").
#include <string>

namespace foveate::app {

/// An argument as a POSIX shell needs it to read it back unchanged: as it is
/// when the shell would neither split nor expand it, else single-quoted.
std::string shell_quote(const std::string& a);
/// Stores the command line (main() calls it once).
void set_invocation(int argc, const char* const* argv);
/// "foveate ..." as typed, or empty when main() did not set it (tests).
const std::string& invocation();

}  // namespace foveate::app
