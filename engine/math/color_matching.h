#pragma once
// Colour-matching functions: x̄(λ), ȳ(λ), z̄(λ) tabulated at equal wavelength steps. The engine
// uses the CIE 1931 2° standard observer (CIE 015:2004), read from the data file
// content/data/cie1931_2deg_xyz.cmf (provenance and checks: content/data/PROVENANCE.md).
#include <string>
#include <string_view>
#include <vector>

namespace pyro {

struct ColorMatchingFunctions {
  double start_nm = 0.0;  // wavelength of the first sample
  double step_nm = 0.0;   // spacing of the samples
  std::vector<double> x, y, z;

  std::size_t size() const { return x.size(); }
  double wavelength_nm(std::size_t i) const { return start_nm + step_nm * static_cast<double>(i); }
};

// Parses a CGATS.17 CMF file (colord's format: SPECTRAL_START_NM, SPECTRAL_END_NM,
// SPECTRAL_BANDS, three data sets between BEGIN_DATA and END_DATA). Throws pyro::UserError
// naming `file_name` and the keyword or set that is missing or malformed.
ColorMatchingFunctions parse_cgats_cmf(std::string_view text, const std::string& file_name);

// The CIE 1931 2° observer from the content folder, parsed once and cached.
const ColorMatchingFunctions& cie1931_2deg();

}  // namespace pyro
