#pragma once
// The interval a parameter's numbers must lie in, each end open or closed, and the usual ones.
#include <string>

#include "engine/io/parameter_text.h"

namespace pyro {

// Bound on every quantity whose header comment gives no upper limit (lengths, coordinates,
// speeds, radiances, frame rate): far beyond any sensible scene, far below float overflow,
// and still coarse enough that float keeps ~0.1 world-unit precision at the extremes.
constexpr double kLarge = 1e6;

// An interval of accepted numbers, each end open or closed.
struct Range {
  double lo, hi;
  bool lo_open = false, hi_open = false;

  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const {  // "[0, 1]", "(0, 1e6]"
    return std::string(lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) +
           (hi_open ? ")" : "]");
  }
};

constexpr Range kAnyRange{-kLarge, kLarge};
constexpr Range kPositive{0.0, kLarge, true, false};
constexpr Range kNonNegative{0.0, kLarge};
constexpr Range kUnit{0.0, 1.0};

}  // namespace pyro
