#pragma once
// Seconds elapsed on the steady clock since a time point: the timer of benchmarks, imports and
// progress reports.
#include <chrono>

namespace pyro {

inline double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace pyro
