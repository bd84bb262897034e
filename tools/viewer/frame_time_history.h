#pragma once
// What the profiler panel plots: named series of samples (a system's milliseconds, a layer's
// fragments) over the last `window_seconds` of the viewer's clock. Samples older than the window
// are dropped as new ones arrive, so memory stays bounded however long the viewer runs.
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace pyro {

class FrameTimeHistory {
 public:
  explicit FrameTimeHistory(double window_seconds = 5.0) : window_(window_seconds) {}

  // A sample of series `name` at time `t` seconds (non-decreasing across calls).
  void add(const std::string& name, double t, double value);
  // Drops every series' samples older than latest - window.
  void trim(double latest);

  std::vector<std::string> names() const;
  // The samples of `name` in time order (empty when unknown).
  std::vector<float> values(const std::string& name) const;
  double mean(const std::string& name) const;  // 0 when empty
  double max(const std::string& name) const;   // 0 when empty
  double window_seconds() const { return window_; }

 private:
  struct Sample {
    double t, value;
  };
  double window_;
  std::map<std::string, std::deque<Sample>> series_;
};

}  // namespace pyro
