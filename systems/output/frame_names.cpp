#include "systems/output/frame_names.h"

#include <cstdio>

namespace pyro {

std::string frame_stem(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d", index);
  return name;
}

std::vector<std::string> frame_view_stems(int index, bool two_views) {
  const std::string stem = frame_stem(index);
  if (two_views) return {stem + "_left", stem + "_right"};
  return {stem};
}

}  // namespace pyro
