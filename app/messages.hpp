#pragma once
// The command line's side of the library's messages: each field of the
// library's options written as the flag that sets it, notices printed on
// stderr by the verbosity asked for, and a frame past --frame-timeout ending
// the process.
#include <string>

#include "foveate/bench/bench.hpp"

namespace foveate::app {

/// The flag that sets a field of foveate::bench's options ("frames" ->
/// "--frames"); empty for a field no flag sets.
std::string flag_for(const std::string& field);
/// `text` with every field it names written as its flag.
std::string with_flags(const bench::FieldText& text);

/// Prints a notice on stderr: details with --verbose, notes and warnings
/// unless --quiet.
void print_notice(const bench::Notice& notice);
/// What every command that renders hands the library: notices printed, and
/// a frame past --frame-timeout ending the process (a GL draw cannot be
/// interrupted).
bench::SessionCallbacks session_callbacks();

}  // namespace foveate::app
