#pragma once
// A run of output frames: "N" (frames 0 .. N-1) or "A:B" (frames A .. B, both included, as
// render farms' job schedulers split sequences). Frame numbers are absolute: frame f is the
// scene after f frames (frame_sequencer.h), whichever frames are drawn.
#include <string>

namespace pyro {

struct FrameRange {
  int first = 0;
  int last = 0;  // inclusive, >= first
  int count() const { return last - first + 1; }
};

// Throws UserError naming `argument` when `text` is not "N" with 1 <= N <= 1,000,000 or "A:B"
// with 0 <= A <= B < 1,000,000.
FrameRange parse_frame_range(const std::string& text, const std::string& argument);

}  // namespace pyro
