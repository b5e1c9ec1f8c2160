#include "foveate/gpu/profiler.hpp"

#include <algorithm>

#include "foveate/gpu/frame.hpp"

namespace foveate::gpu {

namespace {
PassProfiler* g_current = nullptr;
}

PassProfiler::Clock PassProfiler::clock_for_current_renderer() {
  return FrameTimer::gpu_timer_meaningful() ? Clock::TimerQuery : Clock::Finish;
}

PassProfiler::PassProfiler(Clock clock) : clock_(clock) {}

PassProfiler::~PassProfiler() {
  if (g_current == this) g_current = nullptr;
  if (!queries_.empty()) glDeleteQueries(static_cast<GLsizei>(queries_.size()), queries_.data());
}

PassProfiler* PassProfiler::current() { return g_current; }

void PassProfiler::begin_frame() {
  g_current = this;
  depth_ = 0;
  used_ = 0;
  pending_.clear();
  frame_.clear();
}

GLuint PassProfiler::timestamp_query() {
  if (used_ == queries_.size()) {
    GLuint q = 0;
    glGenQueries(1, &q);
    queries_.push_back(q);
  }
  const GLuint q = queries_[used_++];
  glQueryCounter(q, GL_TIMESTAMP);
  return q;
}

void PassProfiler::begin(const char* name) {
  if (depth_++ > 0) return;
  open_.name = name;
  if (clock_ == Clock::Finish) {
    glFinish();
    open_.t0 = std::chrono::steady_clock::now();
  } else {
    timestamp_query();
    open_.query = used_ - 1;
  }
}

void PassProfiler::end() {
  if (depth_ == 0 || --depth_ > 0) return;
  double ms = 0.0;
  if (clock_ == Clock::Finish) {
    glFinish();
    ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - open_.t0)
             .count();
  } else {
    timestamp_query();
    pending_.push_back({open_.name, {open_.query, used_ - 1}});
    ms = 0.0;  // filled in at end_frame
  }
  auto it = std::find_if(frame_.begin(), frame_.end(),
                         [&](const PassTime& p) { return p.name == open_.name; });
  if (it == frame_.end()) {
    frame_.push_back({open_.name, ms});
  } else {
    it->ms += ms;
  }
}

const std::vector<PassTime>& PassProfiler::end_frame() {
  if (g_current == this) g_current = nullptr;
  for (const auto& [name, pair] : pending_) {
    GLuint64 t0 = 0, t1 = 0;
    glGetQueryObjectui64v(queries_[pair.first], GL_QUERY_RESULT, &t0);
    glGetQueryObjectui64v(queries_[pair.second], GL_QUERY_RESULT, &t1);
    auto it = std::find_if(frame_.begin(), frame_.end(),
                           [&](const PassTime& p) { return p.name == name; });
    if (it != frame_.end() && t1 >= t0) it->ms += static_cast<double>(t1 - t0) * 1e-6;
  }
  pending_.clear();
  return frame_;
}

}  // namespace foveate::gpu
