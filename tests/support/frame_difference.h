#pragma once
// How a rendered PNG frame differs from a reference PNG: the largest difference of one value (of
// 255), the share of values that differ at all, and whether the files are the same bytes; printed
// as one line, for the tests that hold frames to earlier renders.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "engine/io/png_file.h"
#include "tests/support/file_bytes.h"

namespace pyro::test {

struct FrameDifference {
  int largest = 0;
  double share = 0.0;
  bool same_bytes = false;
};

// Fails the calling test (ASSERT) when the sizes differ; prints "NAME: the same bytes, ...".
inline void compare_frames(const std::string& name, const std::filesystem::path& now,
                           const std::filesystem::path& before, FrameDifference& out) {
  const PngImage a = read_png(now.string()), b = read_png(before.string());
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const int d = std::abs(int(a.pixels[i]) - int(b.pixels[i]));
    out.largest = std::max(out.largest, d);
    differing += d > 0 ? 1 : 0;
  }
  out.share = double(differing) / double(a.pixels.size());
  out.same_bytes = read_bytes(now) == read_bytes(before);
  std::printf("%s: %s, largest difference %d of 255, %.3f%% of the values differ\n", name.c_str(),
              out.same_bytes ? "the same bytes" : "different bytes", out.largest, 100.0 * out.share);
}

}  // namespace pyro::test
