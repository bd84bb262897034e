// Particles drawn into a reduced-resolution layer: the error against full resolution grows as
// the layer shrinks but stays small for this soft medium, opaque geometry still hides particles
// (the layer gets the scene's depth), and the final composition (layer folded in on the fly)
// matches the linear readback (layer blended into the scene) to one 8-bit step.
#include <gtest/gtest.h>

#include <cmath>

#include "components/frame_image.h"
#include "components/gpu_frame.h"
#include "systems/runtime/scene/scene_loader.h"
#include "engine/math/color.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

double rmse_particle_layer(const std::vector<float>& a, const std::vector<float>& b) {
  double s = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = a[i] - b[i];
    s += d * d;
    ++n;
  }
  return std::sqrt(s / n);
}

struct Rendered {
  std::vector<float> linear;
  std::vector<uint8_t> output;
};

Rendered render_particle_layer(float layer_scale) {
  RuntimeOptions o;
  o.width_override = 160;
  o.height_override = 120;
  o.layer_scale = layer_scale;
  SceneRuntime r(load_scene(test::scene_path("fog.json")), o);
  r.step();
  return {r.image().rgba, r.world().resource<GpuFrame>().output->read_rgba8()};
}

TEST(ParticleLayer, ErrorGrowsAsTheLayerShrinksAndStaysSmall) {
  const Rendered full = render_particle_layer(1.0f);
  double previous = 0.0;
  for (float scale : {0.5f, 0.25f, 0.125f}) {
    const double e = rmse_particle_layer(render_particle_layer(scale).linear, full.linear);
    EXPECT_GT(e, previous) << "scale " << scale;
    EXPECT_LT(e, 0.05) << "scale " << scale;
    previous = e;
  }
  EXPECT_GT(previous, 1e-3) << "a 1/8 layer cannot be exact";
}

TEST(ParticleLayer, FinalCompositionMatchesTheLinearReadback) {
  for (float scale : {1.0f, 0.25f}) {
    const Rendered r = render_particle_layer(scale);
    int worst = 0;
    for (size_t p = 0; p < r.linear.size() / 4; ++p)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(static_cast<int>(r.output[p * 4 + c]) -
                                         to_byte(linear_to_srgb(r.linear[p * 4 + c]))));
    EXPECT_LE(worst, 1) << "scale " << scale;
  }
}

}  // namespace
}  // namespace pyro
