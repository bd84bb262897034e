#include "systems/runtime/scene_runtime/frame_range.h"

#include <charconv>

#include "engine/core/user_error.h"

namespace pyro {

namespace {

constexpr int kMaxFrames = 1'000'000;

// A whole decimal number in [0, kMaxFrames], all of `text`; -1 otherwise.
int parse_count(const std::string& text) {
  int value = -1;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || value < 0 || value > kMaxFrames) return -1;
  return value;
}

}  // namespace

FrameRange parse_frame_range(const std::string& text, const std::string& argument) {
  const std::string expected =
      "expected a frame count N (1 to 1000000) or an inclusive range A:B with 0 <= A <= B < "
      "1000000, found \"" + text + "\"";
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) {
    const int n = parse_count(text);
    if (n < 1) throw UserError("command line", argument, expected);
    return {0, n - 1};
  }
  const int a = parse_count(text.substr(0, colon));
  const int b = parse_count(text.substr(colon + 1));
  if (a < 0 || b < 0 || a > b || b >= kMaxFrames) throw UserError("command line", argument, expected);
  return {a, b};
}

}  // namespace pyro
