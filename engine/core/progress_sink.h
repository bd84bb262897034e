#pragma once
// How long work (benchmarks, chart sets, imports) says how far it is, without printing: it
// reports to a ProgressSink, which the command line draws as a bar on a terminal
// (tools/pyro/progress.h) and an embedding program may show or ignore. No sink: nothing.
#include <cstddef>
#include <string>

namespace pyro {

class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  // A task of `total` steps named `label` begins (the previous one, if any, has finished).
  virtual void begin(const std::string& label, size_t total) = 0;
  // `done` steps finished; the one running now is called `stage` (empty: unnamed).
  virtual void update(size_t done, const std::string& stage) = 0;
  virtual void finish() = 0;
};

// One task on a sink (which may be null): begun on construction, finished when it ends.
class ProgressTask {
 public:
  ProgressTask(ProgressSink* sink, const std::string& label, size_t total) : sink_(sink) {
    if (sink_) sink_->begin(label, total);
  }
  ~ProgressTask() { finish(); }
  ProgressTask(const ProgressTask&) = delete;
  ProgressTask& operator=(const ProgressTask&) = delete;

  void update(size_t done) { stage(done, stage_); }
  void stage(size_t done, const std::string& stage) {
    stage_ = stage;
    if (sink_) sink_->update(done, stage_);
  }
  void finish() {
    if (sink_) sink_->finish();
    sink_ = nullptr;
  }

 private:
  ProgressSink* sink_;
  std::string stage_;
};

}  // namespace pyro
