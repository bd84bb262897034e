// Black-body colour (Umenhoffer et al. 2006, section 3.2) from Planck's law and the CIE 1931 2°
// observer, against published chromaticities and the colour-matching functions' invariants.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/math/blackbody.h"

namespace pyro {
namespace {

TEST(ColorMatching, DataFileIsTheCie1931Observer) {
  const ColorMatchingFunctions& c = cie1931_2deg();
  ASSERT_EQ(c.size(), 95u);
  EXPECT_DOUBLE_EQ(c.start_nm, 360.0);
  EXPECT_DOUBLE_EQ(c.step_nm, 5.0);
  // Anchor values of CIE 015:2004 table T.4: ȳ(555) = 1, x̄(555) = 0.5120501, z̄(445) = 1.7826.
  EXPECT_DOUBLE_EQ(c.y[(555 - 360) / 5], 1.0);
  EXPECT_DOUBLE_EQ(c.x[(555 - 360) / 5], 0.5120501);
  EXPECT_DOUBLE_EQ(c.z[(445 - 360) / 5], 1.7826);
}

TEST(ColorMatching, CopyEqualsTheDebianPackagesFile) {
  const std::string packaged = "/usr/share/colord/cmf/CIE1931-2deg-XYZ.cmf";
  if (!std::filesystem::exists(packaged)) GTEST_SKIP() << "colord-data is not installed";
  EXPECT_EQ(read_text_file(content_path("data/cie1931_2deg_xyz.cmf")), read_text_file(packaged));
}

TEST(ColorMatching, MalformedFilesAreUserErrors) {
  EXPECT_THROW(parse_cgats_cmf("CMF\nSPECTRAL_END_NM 830\n", "f.cmf"), UserError);
  EXPECT_THROW(parse_cgats_cmf("SPECTRAL_START_NM 360\nSPECTRAL_END_NM 370\nSPECTRAL_BANDS 3\n"
                               "BEGIN_DATA\n1 2 3\n4 5 6\n7 8\nEND_DATA\n",
                               "f.cmf"),
               UserError);
  const ColorMatchingFunctions ok = parse_cgats_cmf(
      "SPECTRAL_START_NM 360\nSPECTRAL_END_NM 370\nSPECTRAL_BANDS 3\nBEGIN_DATA\n1 2 3\n4 5 6\n7 8 9\nEND_DATA\n",
      "f.cmf");
  EXPECT_DOUBLE_EQ(ok.step_nm, 5.0);
  EXPECT_DOUBLE_EQ(ok.z[2], 9.0);
}

TEST(Blackbody, EqualEnergyWhiteIsAtOneThird) {
  // The CMFs are scaled to equal areas, so S(λ) = 1 lands at x = y = 1/3.
  const glm::dvec2 xy = xyz_chromaticity(equal_energy_xyz());
  EXPECT_NEAR(xy.x, 1.0 / 3.0, 1e-4);
  EXPECT_NEAR(xy.y, 1.0 / 3.0, 1e-4);
}

TEST(Blackbody, PlanckMatchesWiensDisplacementAndStefanBoltzmann) {
  // Independent closed forms of Planck's law: the peak at b / T (b = 2.897771955e-3 m K) and
  // π ∫ L_λ dλ = σ T⁴ (σ = 5.670374419e-8 W m⁻² K⁻⁴).
  const double t = 2856.0;
  double best = 0.0, best_l = 0.0, sum = 0.0;
  const double h = 1e-10;
  for (double l = h; l < 2e-4; l += h) {
    const double v = planck_radiance(l, t);
    sum += v * h;
    if (v > best) best = v, best_l = l;
  }
  EXPECT_NEAR(best_l, 2.897771955e-3 / t, 2e-10);
  EXPECT_NEAR(std::numbers::pi * sum / (5.670374419e-8 * t * t * t * t), 1.0, 1e-4);
}

TEST(Blackbody, IlluminantAAt2856K) {
  // CIE illuminant A: a black body at 2856 K (on the 1968 temperature scale), (0.44757, 0.40745).
  const BlackbodyColor c = blackbody_color(2856.0);
  EXPECT_NEAR(c.xy.x, 0.44757, 1e-3);
  EXPECT_NEAR(c.xy.y, 0.40745, 1e-3);
  // Tighter than the bar: the 5 nm table leaves about 4e-5.
  EXPECT_NEAR(c.xy.x, 0.44757, 1e-4);
  EXPECT_NEAR(c.xy.y, 0.40745, 1e-4);
}

TEST(Blackbody, D65NeighbourAt6504K) {
  // The Planckian point at D65's correlated colour temperature, 6504 K: (0.3135, 0.3236)
  // (D65 itself, (0.3127, 0.3290), lies off the locus).
  const BlackbodyColor c = blackbody_color(6504.0);
  EXPECT_NEAR(c.xy.x, 0.3135, 5e-4);
  EXPECT_NEAR(c.xy.y, 0.3236, 5e-4);
}

TEST(Blackbody, SrgbMatrixMapsD65WhiteToGrey) {
  const double x = 0.3127, y = 0.3290;
  const glm::dvec3 rgb = xyz_to_linear_srgb({x / y, 1.0, (1.0 - x - y) / y});
  EXPECT_NEAR(rgb.x, 1.0, 1e-3);
  EXPECT_NEAR(rgb.y, 1.0, 1e-3);
  EXPECT_NEAR(rgb.z, 1.0, 1e-3);
}

TEST(Blackbody, LinearSrgbChromaticityUndoesTheMatrix) {
  // Grey is D65's white point; an in-gamut black body's colour, at any scale, is its own xy.
  const glm::dvec2 white = linear_srgb_chromaticity({0.7, 0.7, 0.7});
  EXPECT_NEAR(white.x, 0.3127, 2e-4);
  EXPECT_NEAR(white.y, 0.3290, 2e-4);
  for (double t : {2500.0, 4000.0, 6504.0}) {
    const BlackbodyColor c = blackbody_color(t);
    ASSERT_TRUE(c.in_gamut) << t;
    const glm::dvec2 xy = linear_srgb_chromaticity(3.0 * c.rgb);
    EXPECT_NEAR(xy.x, c.xy.x, 1e-9) << t;
    EXPECT_NEAR(xy.y, c.xy.y, 1e-9) << t;
  }
}

TEST(Blackbody, ColourMovesFromRedToBlueAsTemperatureRises) {
  double last_x = 1.0, last_blue_over_red = 0.0, last_luminance = 0.0, last_rgb_ratio = 0.0;
  for (double t = 1000.0; t <= 12000.0; t += 250.0) {
    const BlackbodyColor c = blackbody_color(t);
    EXPECT_LT(c.xy.x, last_x) << t;  // x falls monotonically along the Planckian locus
    // Unclamped: Z / X rises strictly; the displayable rgb's blue / red never falls (it is 0
    // while blue is out of the sRGB gamut, below about 1900 K).
    const double blue_over_red = c.xyz.z / c.xyz.x;
    EXPECT_GT(blue_over_red, last_blue_over_red) << t;
    EXPECT_GE(c.rgb.z / c.rgb.x, last_rgb_ratio) << t;
    last_rgb_ratio = c.rgb.z / c.rgb.x;
    EXPECT_GT(c.luminance, last_luminance) << t;  // and it gets brighter
    EXPECT_NEAR(std::max({c.rgb.x, c.rgb.y, c.rgb.z}), 1.0, 1e-12);
    last_x = c.xy.x;
    last_blue_over_red = blue_over_red;
    last_luminance = c.luminance;
  }
  // Fire's range (paper: 2500–3200 K) is red-dominant; 12000 K is blue-dominant.
  EXPECT_EQ(blackbody_color(2500.0).rgb.x, 1.0);
  EXPECT_EQ(blackbody_color(12000.0).rgb.z, 1.0);
}

TEST(Blackbody, TableSamplesMatchDirectEvaluation) {
  const BlackbodyTable table = make_blackbody_table(1000.0, 12000.0, 1101);
  ASSERT_EQ(table.rgb.size(), 1101u * 3);
  for (double t : {1000.0, 2856.0, 3000.0, 6504.0, 12000.0}) {
    const glm::vec3 s = sample_blackbody_rgb(table, t);
    const BlackbodyColor c = blackbody_color(t);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s[k], c.rgb[k], 2e-3) << t << " " << k;
  }
  // Clamped beyond the ends.
  EXPECT_EQ(sample_blackbody_rgb(table, 500.0), sample_blackbody_rgb(table, 1000.0));
}

}  // namespace
}  // namespace pyro
