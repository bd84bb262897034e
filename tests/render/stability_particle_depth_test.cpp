// Optical depth across one particle from 0.01 to the densest a splat holds (rho = 1): a lone
// Gaussian lit from the side, drawn by the engine and by the CPU reference that integrates its
// exact transmittance toward the sun at every point of every ray. Lit without its own shadow (the
// naive light: the sun's full colour wherever the particle is) it drifts from the reference as the
// particle thickens (RMSE over the frame 0.04 at tau0 = 1, 0.15 at 3, 0.39 at rho = 1). With its
// own shadow every pixel stays finite and the error stays within a sixth of that (measured 0.0001,
// 0.0007, 0.0065, 0.017, 0.025, 0.037): a thin particle is lit at each fragment's point of
// closest approach, a thick one (tau0 >= 1) from the opacity map where the eye sees it along the
// pixel's ray, its near side (splat_sunlight.glsl). Lit at the closest approach alone, a thick
// particle's error grew to 0.015, 0.047, 0.087 and 0.121: one point cannot see the particle's lit
// front from its shadowed back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/reference_rmse.h"

namespace pyro {
namespace {

SceneDescription lone_particle(double density, const char* method) {
  const std::string json = std::string(R"({"name": "lone particle", "seed": 1, "output": {"width": 96, "height": 96},
      "background": [0.2, 0.25, 0.3],
      "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40},
      "light": {"direction": [-1, 0, 0], "color": [1, 1, 1], "ambient": [0.1, 0.1, 0.1]},
      "shadows": {"method": ")") + method + R"("},
      "clouds": [{"count": 1, "radius": 1.2, "color": 0.9, "jitter": 0, "density": )" +
                           std::to_string(density) + R"(, "box": {"min": [-1e-4, -1e-4, -1e-4], "max": [1e-4, 1e-4, 1e-4]}}]})";
  return parse_scene(json, "lone_particle.json");
}


struct DepthCase {
  double tau0;
  double bound;  // the engine's RMSE over the frame, measured, with a margin
};

void PrintTo(const DepthCase& c, std::ostream* os) { *os << "tau0 " << c.tau0; }

class StabilityParticleDepth : public ::testing::TestWithParam<DepthCase> {};

TEST_P(StabilityParticleDepth, OwnShadowKeepsTheSplatNearTheReference) {
  const double tau0 = GetParam().tau0, density = tau0 > 50.0 ? 1.0 : -std::expm1(-tau0);
  const double lit = test::rmse_against_cpu_reference(lone_particle(density, "map"), 96, 96);
  EXPECT_TRUE(std::isfinite(lit));
  EXPECT_LT(lit, GetParam().bound) << "tau0 " << tau0;
  std::printf("tau0 %g: own shadow %.4f", tau0, lit);
  if (tau0 >= 1.0) {
    const double naive = test::rmse_against_cpu_reference(lone_particle(density, "none"), 96, 96);
    std::printf(", without it %.4f", naive);
    EXPECT_GT(naive, 2.0 * lit) << "tau0 " << tau0;
  }
  std::printf("\n");
}

INSTANTIATE_TEST_SUITE_P(FromThinToOpaque, StabilityParticleDepth,
                         ::testing::Values(DepthCase{0.01, 0.001}, DepthCase{0.1, 0.002}, DepthCase{1.0, 0.009},
                                           DepthCase{3.0, 0.022}, DepthCase{10.0, 0.033}, DepthCase{100.0, 0.047}),
                         [](const auto& info) {
                           const double t = info.param.tau0;
                           return t < 0.05 ? std::string("Tau0_001") : t < 0.5 ? std::string("Tau0_01")
                                  : t < 2 ? std::string("Tau0_1") : t < 5 ? std::string("Tau0_3")
                                  : t < 50 ? std::string("Tau0_10") : std::string("Rho1");
                         });

}  // namespace
}  // namespace pyro
