// The closed form of a shadow: a uniform slab of Gaussian particles between a vertical sun and
// the ground leaves exp(-tau) of the sunlight on the ground, tau the slab's optical depth. The
// slab is a square lattice of particles of standard deviation s, spacing h = s / 2 in x and z,
// n layers deep; each particle's column through its axis is tau0 = -ln(1 - rho), so far from
// the slab's edges (Poisson summation; the lattice's ripple is below 1e-9 at h = s / 2)
//   tau = n tau0 2 pi s^2 erf(3 / sqrt 2)^2 / h^2
// (the kernel clamped to +-3 s across the column: erf(3 / sqrt 2) per axis). The ground (albedo 1,
// sun 1, no ambient, light straight down) then shows exp(-tau) itself, read from the frame's
// half-float scene target; both shadow methods must match it to 1e-3.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>

#include "components/gpu_frame.h"
#include "engine/io/particle_file.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

constexpr float kRadius = 0.3f, kDensity = 0.02f;
constexpr int kLayers = 3, kHalfWidth = 24;  // (2 kHalfWidth + 1)^2 particles a layer

double slab_optical_depth() {
  const double s = kRadius / 3.0, h = s / 2.0, tau0 = -std::log(1.0 - kDensity);
  const double clamp = std::erf(3.0 / std::numbers::sqrt2);
  return kLayers * tau0 * 2.0 * std::numbers::pi * s * s * clamp * clamp / (h * h);
}

std::string write_slab_scene(const std::filesystem::path& dir, const char* method) {
  ParticleFile slab;
  const float h = kRadius / 6.0f;
  for (int l = 0; l < kLayers; ++l)
    for (int i = -kHalfWidth; i <= kHalfWidth; ++i)
      for (int k = -kHalfWidth; k <= kHalfWidth; ++k)
        slab.particles.push_back({i * h, 3.0f + l * h, k * h, kRadius, kDensity, 1.0f, 1.0f, 1.0f});
  write_particle_file((dir / "slab.pyrop").string(), slab);
  const std::string scene = (dir / (std::string(method) + ".json")).string();
  std::ofstream(scene) << R"({
    "background": [0, 0, 0],
    "camera": {"position": [0, 1.5, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_y_deg": 20, "near": 0.1, "far": 10},
    "lights": [{"type": "directional", "direction": [0, -1, 0], "color": [1, 1, 1]}],
    "shadows": {"method": ")" << method << R"(", "map_size": 64, "map_slices": 16},
    "volumes": [{"file": "slab.pyrop", "anchor": "origin"}],
    "meshes": [{"type": "ground_plane", "scale": 20, "color": [1, 1, 1]}]
  })";
  return scene;
}

// The mean of the ground's red channel over the frame's centre (the scene target, before it is
// encoded to 8 bits).
double ground_under_the_slab(const std::string& scene_file) {
  RuntimeOptions o;
  o.readback = true;
  o.width_override = 32;
  o.height_override = 32;
  SceneRuntime runtime(load_scene(scene_file), o);
  runtime.draw_frame(0);
  const std::vector<float> rgba = runtime.world().resource<GpuFrame>().eyes.at(0).scene->read_rgba();
  double sum = 0.0;
  int n = 0;
  for (int y = 12; y < 20; ++y)
    for (int x = 12; x < 20; ++x, ++n) sum += rgba[4 * (size_t(y) * 32 + x)];
  return sum / n;
}

TEST(SlabShadow, TheGroundKeepsExpMinusTauOfTheSunlight) {
  const std::filesystem::path dir = test::scratch_dir("slab_shadow");
  const double expected = std::exp(-slab_optical_depth());
  ASSERT_GT(slab_optical_depth(), 0.5);  // a shadow worth measuring
  for (const char* method : {"rays", "map"}) {
    const double ground = ground_under_the_slab(write_slab_scene(dir, method));
    std::printf("%s: ground %.6f, exp(-tau) %.6f (tau %.4f)\n", method, ground, expected, slab_optical_depth());
    EXPECT_NEAR(ground, expected, 1e-3) << method;
  }
  // Lit without shadows, the ground keeps the whole sun.
  EXPECT_NEAR(ground_under_the_slab(write_slab_scene(dir, "none")), 1.0, 1e-3);
}

}  // namespace
}  // namespace pyro
