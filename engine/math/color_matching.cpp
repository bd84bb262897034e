#include "engine/math/color_matching.h"

#include <cmath>
#include <sstream>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"

namespace pyro {

namespace {

// The value after `key` on its line ("KEY<whitespace>value"), or throws.
double keyword_number(std::string_view text, std::string_view key, const std::string& file) {
  std::size_t pos = 0;
  while ((pos = text.find(key, pos)) != std::string_view::npos) {
    const bool line_start = pos == 0 || text[pos - 1] == '\n';
    const std::size_t after = pos + key.size();
    if (line_start && after < text.size() && (text[after] == ' ' || text[after] == '\t')) {
      std::istringstream in{std::string(text.substr(after, text.find('\n', after) - after))};
      double v = 0.0;
      if (in >> v) return v;
      throw UserError(file, std::string(key), "expected a number after the keyword");
    }
    pos = after;
  }
  throw UserError(file, std::string(key), "missing keyword");
}

}  // namespace

ColorMatchingFunctions parse_cgats_cmf(std::string_view text, const std::string& file) {
  ColorMatchingFunctions cmf;
  cmf.start_nm = keyword_number(text, "SPECTRAL_START_NM", file);
  const double end_nm = keyword_number(text, "SPECTRAL_END_NM", file);
  const double bands = keyword_number(text, "SPECTRAL_BANDS", file);
  if (bands < 2 || bands != std::floor(bands) || !(end_nm > cmf.start_nm))
    throw UserError(file, "SPECTRAL_BANDS", "expected at least 2 bands over an increasing range");
  const auto n = static_cast<std::size_t>(bands);
  cmf.step_nm = (end_nm - cmf.start_nm) / static_cast<double>(n - 1);

  const std::size_t begin = text.find("\nBEGIN_DATA\n");
  const std::size_t end = text.find("\nEND_DATA", begin == std::string_view::npos ? 0 : begin);
  if (begin == std::string_view::npos || end == std::string_view::npos)
    throw UserError(file, "BEGIN_DATA", "expected a BEGIN_DATA ... END_DATA block");
  const std::string_view block = text.substr(begin + 12, end - (begin + 12));
  std::istringstream in{std::string(block)};
  std::vector<double>* sets[3] = {&cmf.x, &cmf.y, &cmf.z};
  const char* names[3] = {"x-bar", "y-bar", "z-bar"};
  for (int s = 0; s < 3; ++s) {
    sets[s]->resize(n);
    for (std::size_t i = 0; i < n; ++i)
      if (!(in >> (*sets[s])[i]))
        throw UserError(file, std::string("BEGIN_DATA, set ") + names[s],
                        "expected " + std::to_string(n) + " numbers, found " + std::to_string(i));
  }
  double extra = 0.0;
  if (in >> extra)
    throw UserError(file, "BEGIN_DATA", "expected exactly 3 sets of " + std::to_string(n) + " numbers");
  return cmf;
}

const ColorMatchingFunctions& cie1931_2deg() {
  static const ColorMatchingFunctions cmf = [] {
    const std::string path = content_path("data/cie1931_2deg_xyz.cmf");
    return parse_cgats_cmf(read_text_file(path), path);
  }();
  return cmf;
}

}  // namespace pyro
