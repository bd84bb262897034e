#pragma once
// Summary statistics of a sample of timings (or any numbers): mean, median, 95th percentile.
// Percentiles use the nearest-rank definition: the smallest sample with at least p% of the
// samples at or below it, p-th = sorted[ceil(p/100 * n) - 1] (Hyndman & Fan 1996,
// "Sample quantiles in statistical packages", definition 1). So min <= median <= p95 <= max.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace pyro {

struct SampleStatistics {
  std::size_t count = 0;
  double mean = 0.0, median = 0.0, p95 = 0.0, min = 0.0, max = 0.0;
};

// Nearest-rank percentile of an ascending sample; p in (0, 100]. 0 for an empty sample.
inline double nearest_rank_percentile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0.0;
  const double rank = std::ceil(p / 100.0 * static_cast<double>(sorted.size()));
  const std::size_t index = static_cast<std::size_t>(std::max(rank, 1.0)) - 1;
  return sorted[std::min(index, sorted.size() - 1)];
}

inline SampleStatistics sample_statistics(std::vector<double> values) {
  SampleStatistics s;
  s.count = values.size();
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / static_cast<double>(values.size());
  s.median = nearest_rank_percentile(values, 50.0);
  s.p95 = nearest_rank_percentile(values, 95.0);
  s.min = values.front();
  s.max = values.back();
  return s;
}

}  // namespace pyro
