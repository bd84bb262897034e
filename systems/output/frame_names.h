#pragma once
// How output frames are named: frame_0000, frame_0001, ... (the stem; sinks add a view suffix and
// their extension).
#include <string>
#include <vector>

namespace pyro {

std::string frame_stem(int index);

// The per-view stems of frame `index`: {stem} for one view, {stem_left, stem_right} for two.
std::vector<std::string> frame_view_stems(int index, bool two_views);

}  // namespace pyro
