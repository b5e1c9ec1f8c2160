#include "process_stats.hpp"

#include <malloc.h>

#include <fstream>
#include <string>

#include "foveate/gpu/gl.hpp"

namespace foveate::app {

namespace {
/// A "Key:   N kB" line of /proc/self/status, in kB (-1 when unavailable).
long status_kb(const std::string& key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key + ":", 0) == 0) return std::stol(line.substr(key.size() + 1));
  }
  return -1;
}
}  // namespace

std::string process_stats_line(int frame) {
  const gpu::GlObjectCounts gl = gpu::live_gl_objects();
  const struct mallinfo2 m = mallinfo2();
  std::string s = "stats frame=" + std::to_string(frame);
  s += " rss_kb=" + std::to_string(status_kb("VmRSS"));
  s += " heap_kb=" + std::to_string((m.uordblks + m.hblkhd) / 1024);
  s += " gl_total=" + std::to_string(gl.total());
  s += " gl_buffers=" + std::to_string(gl.buffers);
  s += " gl_textures=" + std::to_string(gl.textures);
  s += " gl_framebuffers=" + std::to_string(gl.framebuffers);
  s += " gl_renderbuffers=" + std::to_string(gl.renderbuffers);
  s += " gl_vertex_arrays=" + std::to_string(gl.vertex_arrays);
  s += " gl_programs=" + std::to_string(gl.programs);
  s += " gl_shaders=" + std::to_string(gl.shaders);
  s += " gl_queries=" + std::to_string(gl.queries);
  return s;
}

}  // namespace foveate::app
