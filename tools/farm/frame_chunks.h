#pragma once
// A farm's frames as job-array tasks: a range A:B cut into chunks of K frames, and what a set of
// finished frames lacks, as the ranges to name in a report and to render again.
#include <set>
#include <string>
#include <vector>

#include "systems/runtime/scene_runtime/frame_range.h"

namespace pyro {

// `range` in consecutive chunks of `chunk` frames, in order; the last holds what is left (it may
// be shorter). Throws std::invalid_argument for a chunk below 1 (the command checks it first).
std::vector<FrameRange> chunk_frames(const FrameRange& range, int chunk);

// Each of `ranges` cut into chunks of `chunk` frames, in order: a chunk never spans two ranges,
// so a resubmission renders only what is missing.
std::vector<FrameRange> chunk_ranges(const std::vector<FrameRange>& ranges, int chunk);

// The frames of `range` not in `present`, as maximal runs of consecutive frames, in order.
std::vector<FrameRange> missing_ranges(const FrameRange& range, const std::set<int>& present);

// "A:B" as `pyro render --frames` reads it (a single frame is "A:A": "A" alone would be a count).
std::string range_text(const FrameRange& range);
// "A:B, C:D".
std::string ranges_text(const std::vector<FrameRange>& ranges);

}  // namespace pyro
