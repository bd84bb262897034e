// A dense cumulus: the `clouds` scene with 10,000 particles instead of 1,500, at densities where
// the optical depth across one particle (tau0 = -ln(1 - rho): 1.2 at rho = 0.7, 2.3 at 0.9, 27.6 at
// rho = 1) is large and the medium's depth toward the sun grows by several units across one
// particle, drawn by the engine with the opacity map and by the CPU reference (exact
// transmittance toward the sun along every ray).
//
// The naive light linearizes the sun's depth about each particle's centre and takes it at one
// point of the billboard (`"splat_sunlight": "vertices"`): on the sunward side the extrapolation
// goes negative (white crescents), on the other far too deep. The engine reads the map where the
// eye sees each particle (the median of the light along the pixel's ray, on the near side of a
// dense particle: splat_sunlight.glsl), interpolating the map's transmittance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/quality/quality_settings.h"
#include "systems/runtime/quality_picker/quality_measurement.h"

namespace pyro {
namespace {

SceneDescription dense_cumulus(double density, const char* sunlight) {
  return parse_scene(std::string(R"({"name": "dense cumulus", "seed": 14, "output": {"width": 160, "height": 90},
      "background": [0.35, 0.55, 0.85],
      "camera": {"position": [1.5, 2.2, 14.0], "target": [0.0, 3.6, 0.0], "fov_y_deg": 45},
      "light": {"direction": [-0.5, -1.0, -0.35], "color": [1.0, 0.97, 0.9], "ambient": [0.3, 0.35, 0.45]},
      "clouds": [{"count": 10000, "radius": 0.37, "color": 0.86, "jitter": 0.02, "density": )") +
                         std::to_string(density) + R"(, "box": {"min": [-6.0, 4.0, -6.0], "max": [6.0, 7.5, 6.0]}}],
      "meshes": [{"type": "ground_plane", "scale": 40, "color": [0.3, 0.36, 0.25]}],
      "shadows": {"method": "map", "splat_sunlight": ")" + sunlight + R"("}})",
                     "dense_cumulus.json");
}

struct DenseCase {
  double density;
  double bound;  // the engine's RMSE over the frame, measured, with a margin
};

void PrintTo(const DenseCase& c, std::ostream* os) { *os << "rho " << c.density; }

class StabilityDenseMedium : public ::testing::TestWithParam<DenseCase> {};

TEST_P(StabilityDenseMedium, TheMapReadWhereTheEyeSeesEachParticleHoldsNearTheReference) {
  const double rho = GetParam().density;
  // One truth for both: the reference does not depend on where the splats take their light.
  const QualityGroundTruth truth(dense_cumulus(rho, "fragments"), 160, 90, {0});
  ASSERT_TRUE(truth.cpu_reference());
  for (float v : truth.image(0).rgb) ASSERT_TRUE(std::isfinite(v));
  const double engine = measure_rmse(dense_cumulus(rho, "fragments"), 160, 90, QualitySettings{}, truth);
  const double naive = measure_rmse(dense_cumulus(rho, "vertices"), 160, 90, QualitySettings{}, truth);
  std::printf("rho %g: engine %.4f, linearized at the centre %.4f\n", rho, engine, naive);
  EXPECT_TRUE(std::isfinite(engine));
  EXPECT_LT(engine, GetParam().bound) << "rho " << rho;
  EXPECT_GT(naive, 1.5 * engine) << "rho " << rho;
}

INSTANTIATE_TEST_SUITE_P(ThickToOpaque, StabilityDenseMedium,
                         ::testing::Values(DenseCase{0.9, 0.03}, DenseCase{1.0, 0.062}),
                         [](const auto& info) { return info.param.density < 0.95 ? std::string("Rho09") : std::string("Rho1"); });

}  // namespace
}  // namespace pyro
