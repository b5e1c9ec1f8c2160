#pragma once
// What the library has to tell the user besides its results and errors: a
// line about the set-up (shown when asked for detail), a note (a technique
// left out, a display with nothing to save) or a warning (a gaze trace row
// skipped, a silent eye tracker). The library never prints: a front end
// receives each notice through a callback and decides what to show.
#include <functional>

#include "foveate/bench/field_text.hpp"

namespace foveate::bench {

enum class NoticeKind {
  Detail,   ///< how the run is set up (the renderer, the display, the gaze source)
  Note,     ///< worth knowing; nothing is wrong
  Warning,  ///< something is off, and the run goes on
};

struct Notice {
  NoticeKind kind = NoticeKind::Note;
  FieldText text;
};

using NoticeFn = std::function<void(const Notice&)>;

}  // namespace foveate::bench
