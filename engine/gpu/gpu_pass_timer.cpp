#include "engine/gpu/gpu_pass_timer.h"

#include <stdexcept>
#include <utility>

namespace pyro::gpu {

namespace {
GpuPassTimer* g_active = nullptr;

int64_t steady_ns(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
}
}  // namespace

GpuPassTimer* active_gpu_pass_timer() { return g_active; }
void set_active_gpu_pass_timer(GpuPassTimer* timer) { g_active = timer; }

GpuPassTimer::GpuPassTimer(std::chrono::steady_clock::time_point origin) : origin_(origin) {
  GLint bits = 0;
  glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
  if (bits <= 0)
    throw std::runtime_error("GpuPassTimer: the OpenGL driver has no timestamp counter");
  begin_frame(0);
}

void GpuPassTimer::begin_frame(uint64_t frame) {
  frame_ = frame;
  GLint64 gpu_now = 0;
  glGetInteger64v(GL_TIMESTAMP, &gpu_now);
  offset_ns_ = steady_ns(std::chrono::steady_clock::now()) - static_cast<int64_t>(gpu_now);
}

Query GpuPassTimer::take(std::vector<Query>& pool, GLenum target) {
  if (pool.empty()) return make_query(target);
  Query q = std::move(pool.back());
  pool.pop_back();
  return q;
}

int GpuPassTimer::begin(const std::string& name, bool count_fragments) {
  Pass p;
  p.name = name;
  p.frame = frame_;
  p.offset_ns = offset_ns_;
  p.begin = take(free_timestamps_, GL_TIMESTAMP);
  p.end = take(free_timestamps_, GL_TIMESTAMP);
  if (count_fragments && !counting_) {
    p.samples = take(free_samples_, GL_SAMPLES_PASSED);
    glBeginQuery(GL_SAMPLES_PASSED, p.samples.get());
    counting_ = true;
  }
  glQueryCounter(p.begin.get(), GL_TIMESTAMP);
  passes_.push_back(std::move(p));
  return static_cast<int>(passes_.size()) - 1;
}

void GpuPassTimer::end(int pass) {
  if (pass < 0 || static_cast<size_t>(pass) >= passes_.size() || passes_[size_t(pass)].ended)
    throw std::logic_error("GpuPassTimer::end: no such pass running");
  Pass& p = passes_[size_t(pass)];
  glQueryCounter(p.end.get(), GL_TIMESTAMP);
  if (p.samples) {
    glEndQuery(GL_SAMPLES_PASSED);
    counting_ = false;
  }
  p.ended = true;
}

std::vector<GpuPassSample> GpuPassTimer::collect() {
  std::vector<GpuPassSample> out;
  std::vector<Pass> running;
  const int64_t origin_ns = steady_ns(origin_);
  for (Pass& p : passes_) {
    if (!p.ended) {
      running.push_back(std::move(p));
      continue;
    }
    GLuint64 t0 = 0, t1 = 0;
    glGetQueryObjectui64v(p.begin.get(), GL_QUERY_RESULT, &t0);
    glGetQueryObjectui64v(p.end.get(), GL_QUERY_RESULT, &t1);
    GpuPassSample s;
    s.name = p.name;
    s.frame = p.frame;
    s.start_us = double(static_cast<int64_t>(t0) + p.offset_ns - origin_ns) * 1e-3;
    s.duration_us = t1 > t0 ? double(t1 - t0) * 1e-3 : 0.0;
    if (p.samples) {
      GLuint64 n = 0;
      glGetQueryObjectui64v(p.samples.get(), GL_QUERY_RESULT, &n);
      s.fragments = static_cast<int64_t>(n);
      free_samples_.push_back(std::move(p.samples));
    }
    free_timestamps_.push_back(std::move(p.begin));
    free_timestamps_.push_back(std::move(p.end));
    out.push_back(std::move(s));
  }
  // Handles of running passes are indices: keep them valid by leaving nothing in front.
  if (!running.empty() && running.size() != passes_.size())
    throw std::logic_error("GpuPassTimer::collect: called while a pass is running");
  passes_ = std::move(running);
  return out;
}

GpuPassScope::GpuPassScope(const char* name, bool count_fragments)
    : timer_(active_gpu_pass_timer()) {
  if (timer_) pass_ = timer_->begin(name, count_fragments);
}

GpuPassScope::~GpuPassScope() {
  if (timer_) timer_->end(pass_);
}

}  // namespace pyro::gpu
