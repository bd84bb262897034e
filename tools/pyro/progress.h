#pragma once
// A progress bar for long work (renders of many frames, imports, benchmarks, figure sets), drawn
// on stderr only when stderr is a terminal, so logs and pipes stay clean: a disabled bar writes
// nothing at all. The bar is redrawn in place ('\r') at most ten times a second, and always for
// the last step and when the stage named changes.
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

#include <unistd.h>

#include "engine/core/progress_sink.h"
#include "tools/pyro/interrupt.h"

namespace pyro::cli {

class Progress {
 public:
  // Draws on stderr when stderr is a terminal.
  Progress(std::string label, size_t total)
      : Progress(std::move(label), total, isatty(STDERR_FILENO) != 0, stderr) {}
  // Draws on `out` when `enabled` (tests).
  Progress(std::string label, size_t total, bool enabled, std::FILE* out)
      : label_(std::move(label)), total_(total), enabled_(enabled), out_(out),
        start_(std::chrono::steady_clock::now()) {}
  ~Progress() { finish(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool enabled() const { return enabled_; }

  // Each step is also where a SIGINT or SIGTERM ends the command (tools/pyro/interrupt.h).
  void update(size_t done) {
    throw_if_interrupted();
    draw(done, false);
  }
  // `done` steps finished, and the one now running is called `stage` ("read", "import", ...).
  void stage(size_t done, const std::string& stage) {
    throw_if_interrupted();
    const bool changed = stage != stage_;
    stage_ = stage;
    draw(done, changed);
  }
  void finish() {
    if (drawn_) std::fprintf(out_, "\n");
    drawn_ = false;
  }

 private:
  void draw(size_t done, bool force) {
    if (!enabled_ || total_ == 0) return;
    if (done > total_) done = total_;
    const auto now = std::chrono::steady_clock::now();
    if (!force && drawn_ && done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const int width = 30;
    const int filled = static_cast<int>(width * done / total_);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = done ? elapsed * double(total_ - done) / double(done) : 0.0;
    const std::string suffix = stage_.empty() || done == total_ ? "" : " (" + stage_ + ")";
    std::fprintf(out_, "\r%s [%s%s] %zu/%zu  %.1fs elapsed, %.1fs left%s\033[K", label_.c_str(),
                 std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), done,
                 total_, elapsed, eta, suffix.c_str());
    std::fflush(out_);
    drawn_ = true;
  }

  std::string label_;
  size_t total_;
  bool enabled_;
  std::FILE* out_;
  std::string stage_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_{};
};

// The engine's progress reports (engine/core/progress_sink.h) as a bar on stderr when it is a
// terminal: one Progress per task.
class TerminalProgress : public ProgressSink {
 public:
  void begin(const std::string& label, size_t total) override { bar_.emplace(label, total); }
  void update(size_t done, const std::string& stage) override {
    throw_if_interrupted();
    if (!bar_) return;
    if (stage.empty()) bar_->update(done);
    else bar_->stage(done, stage);
  }
  void finish() override { bar_.reset(); }

 private:
  std::optional<Progress> bar_;
};

// The process's terminal progress, for the commands to hand to long work.
inline ProgressSink* terminal_progress() {
  static TerminalProgress progress;
  return &progress;
}

}  // namespace pyro::cli
