#include "tools/viewer/frame_time_history.h"

#include <algorithm>

namespace pyro {

void FrameTimeHistory::add(const std::string& name, double t, double value) {
  series_[name].push_back({t, value});
}

void FrameTimeHistory::trim(double latest) {
  for (auto it = series_.begin(); it != series_.end();) {
    std::deque<Sample>& s = it->second;
    while (!s.empty() && s.front().t < latest - window_) s.pop_front();
    it = s.empty() ? series_.erase(it) : std::next(it);
  }
}

std::vector<std::string> FrameTimeHistory::names() const {
  std::vector<std::string> out;
  for (const auto& [name, samples] : series_) out.push_back(name);
  return out;
}

std::vector<float> FrameTimeHistory::values(const std::string& name) const {
  std::vector<float> out;
  const auto it = series_.find(name);
  if (it == series_.end()) return out;
  for (const Sample& s : it->second) out.push_back(float(s.value));
  return out;
}

double FrameTimeHistory::mean(const std::string& name) const {
  const auto it = series_.find(name);
  if (it == series_.end() || it->second.empty()) return 0.0;
  double sum = 0.0;
  for (const Sample& s : it->second) sum += s.value;
  return sum / double(it->second.size());
}

double FrameTimeHistory::max(const std::string& name) const {
  const auto it = series_.find(name);
  if (it == series_.end() || it->second.empty()) return 0.0;
  double m = it->second.front().value;
  for (const Sample& s : it->second) m = std::max(m, s.value);
  return m;
}

}  // namespace pyro
