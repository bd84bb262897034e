#pragma once
// A progress bar for long work, drawn on stderr only when stderr is a terminal (so logs and
// pipes stay clean).
#include <chrono>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace pyro::cli {

class Progress {
 public:
  Progress(std::string label, size_t total)
      : label_(std::move(label)), total_(total), enabled_(isatty(STDERR_FILENO) != 0),
        start_(std::chrono::steady_clock::now()) {}
  ~Progress() { finish(); }

  void update(size_t done) {
    if (!enabled_ || total_ == 0) return;
    const auto now = std::chrono::steady_clock::now();
    if (done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const int width = 30;
    const int filled = static_cast<int>(width * done / total_);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = done ? elapsed * (total_ - done) / done : 0.0;
    std::fprintf(stderr, "\r%s [%s%s] %zu/%zu  %.1fs elapsed, %.1fs left ", label_.c_str(),
                 std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), done,
                 total_, elapsed, eta);
    std::fflush(stderr);
    drawn_ = true;
  }
  void finish() {
    if (drawn_) std::fprintf(stderr, "\n");
    drawn_ = false;
  }

 private:
  std::string label_;
  size_t total_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_{};
};

}  // namespace pyro::cli
