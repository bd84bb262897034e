// Every directional light lights the meshes (content/shaders/lights.glsl, mesh.frag): a white
// ground (albedo 1, normal +y) under suns of radiance E_i travelling along d_i and an ambient term
// A shows A + sum_i E_i max(-d_i.y / |d_i|, 0), a closed form, read from the frame's half-float
// scene target. A sun from below adds nothing; sixteen suns (the block's most) all count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "components/gpu_frame.h"
#include "components/light_block.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

struct Sun {
  double x, y, z, radiance;
};

std::string write_ground_scene(const std::filesystem::path& dir, const std::string& name, const std::vector<Sun>& suns,
                               double ambient) {
  std::string lights = R"({"type": "ambient", "color": [)" + std::to_string(ambient) + ", " +
                       std::to_string(ambient) + ", " + std::to_string(ambient) + "]}";
  for (const Sun& s : suns)
    lights += R"(, {"type": "directional", "direction": [)" + std::to_string(s.x) + ", " + std::to_string(s.y) +
              ", " + std::to_string(s.z) + R"(], "color": [1, 1, 1], "intensity": )" + std::to_string(s.radiance) + "}";
  const std::string scene = (dir / (name + ".json")).string();
  std::ofstream(scene) << R"({
    "background": [0, 0, 0],
    "camera": {"position": [0, 1.5, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_y_deg": 20, "near": 0.1, "far": 10},
    "lights": [)" << lights << R"(],
    "meshes": [{"type": "ground_plane", "scale": 20, "color": [1, 1, 1]}]
  })";
  return scene;
}

// The mean of the ground's red channel over the frame's centre, before it is encoded to 8 bits.
double ground_brightness(const std::string& scene_file) {
  RuntimeOptions o;
  o.readback = true;
  o.width_override = 16;
  o.height_override = 16;
  SceneRuntime runtime(load_scene(scene_file), o);
  runtime.draw_frame(0);
  const std::vector<float> rgba = runtime.world().resource<GpuFrame>().eyes.at(0).scene->read_rgba();
  double sum = 0.0;
  int n = 0;
  for (int y = 4; y < 12; ++y)
    for (int x = 4; x < 12; ++x, ++n) sum += rgba[4 * (size_t(y) * 16 + x)];
  return sum / n;
}

double closed_form(const std::vector<Sun>& suns, double ambient) {
  double e = ambient;
  for (const Sun& s : suns) e += s.radiance * std::max(-s.y / std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z), 0.0);
  return e;
}

TEST(MultipleSuns, TheGroundAddsEverySunsLambertianLight) {
  const std::filesystem::path dir = test::scratch_dir("multiple_suns");
  const double ambient = 0.05;
  const std::vector<std::vector<Sun>> cases = {
      {{0, -1, 0, 0.3}},
      {{0, -1, 0, 0.3}, {1, -1, 0, 0.4}},
      {{0, -1, 0, 0.3}, {1, -1, 0, 0.4}, {0, 1, 0, 5.0}},  // from below: no light on the top face
      {{0, -1, 0, 0.3}, {1, -1, 0, 0.4}, {-1, -2, 3, 0.2}},
  };
  for (size_t c = 0; c < cases.size(); ++c) {
    const double seen = ground_brightness(write_ground_scene(dir, "case" + std::to_string(c), cases[c], ambient));
    const double expected = closed_form(cases[c], ambient);
    std::printf("%zu suns: ground %.5f, closed form %.5f\n", cases[c].size(), seen, expected);
    EXPECT_NEAR(seen, expected, 1e-3 * expected) << "case " << c;
  }
  std::vector<Sun> many;
  for (int i = 0; i < kMaxSuns; ++i) many.push_back({std::cos(i * 0.4), -2.0, std::sin(i * 0.4), 0.03});
  const double seen = ground_brightness(write_ground_scene(dir, "many", many, ambient));
  EXPECT_NEAR(seen, closed_form(many, ambient), 1e-3 * closed_form(many, ambient)) << kMaxSuns << " suns";
}

}  // namespace
}  // namespace pyro
