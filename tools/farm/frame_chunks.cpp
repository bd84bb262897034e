#include "tools/farm/frame_chunks.h"

#include <algorithm>
#include <stdexcept>

namespace pyro {

std::vector<FrameRange> chunk_frames(const FrameRange& range, int chunk) {
  if (chunk < 1) throw std::invalid_argument("chunk_frames: a chunk holds at least one frame");
  std::vector<FrameRange> chunks;
  // (In 64 bits: first + chunk may pass INT_MAX for a chunk given as a huge number.)
  for (long long first = range.first; first <= range.last; first += chunk) {
    const long long last = std::min<long long>(first + chunk - 1, range.last);
    chunks.push_back({static_cast<int>(first), static_cast<int>(last)});
  }
  return chunks;
}

std::vector<FrameRange> chunk_ranges(const std::vector<FrameRange>& ranges, int chunk) {
  std::vector<FrameRange> chunks;
  for (const FrameRange& r : ranges) {
    const std::vector<FrameRange> pieces = chunk_frames(r, chunk);
    chunks.insert(chunks.end(), pieces.begin(), pieces.end());
  }
  return chunks;
}

std::vector<FrameRange> missing_ranges(const FrameRange& range, const std::set<int>& present) {
  std::vector<FrameRange> missing;
  for (int f = range.first; f <= range.last; ++f) {
    if (present.count(f)) continue;
    if (!missing.empty() && missing.back().last == f - 1)
      missing.back().last = f;
    else
      missing.push_back({f, f});
  }
  return missing;
}

std::string range_text(const FrameRange& range) {
  return std::to_string(range.first) + ":" + std::to_string(range.last);
}

std::string ranges_text(const std::vector<FrameRange>& ranges) {
  std::string text;
  for (const FrameRange& r : ranges) text += (text.empty() ? "" : ", ") + range_text(r);
  return text;
}

}  // namespace pyro
