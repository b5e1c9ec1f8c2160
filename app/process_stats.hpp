#pragma once
// One line of process statistics for leak hunting (foveate render --stats,
// scripts/soak.sh): resident memory, the heap in use and the live GL objects.
#include <string>

namespace foveate::app {

/// "stats frame=K rss_kb=... heap_kb=... gl_total=... gl_buffers=... ..." (one line, no newline).
std::string process_stats_line(int frame);

}  // namespace foveate::app
