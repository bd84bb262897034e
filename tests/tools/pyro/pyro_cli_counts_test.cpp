// Particle counts are right for every particle kind: a scene of fitted (anisotropic) particles
// reports the particles its file holds in `render --json` and `profile --json`, and the Gaussian
// splats' drawn count is the same whether the CPU or the GPU ordered them.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/io/particle_file.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

TEST(PyroCliCounts, FittedParticlesAreCountedInRenderAndProfile) {
  const size_t in_file = read_particle_file(content_path("volumes/sample_cloud_fitted.pyrop")).anisotropic.size();
  ASSERT_GT(in_file, 0u);
  const fs::path dir = test::scratch_dir("counts_fitted");
  const auto r = test::run_pyro({"render", test::scene_path("cloud_fitted.json"), "--out", (dir / "out").string(),
                                 "--width", "48", "--height", "32", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json summary = test::last_json_line(r.out);
  EXPECT_EQ(summary["particles"].get<size_t>(), in_file);
  EXPECT_EQ(summary["drawn_particles"].get<size_t>(), in_file) << "drawn whole in every view";
  const auto p = test::run_pyro({"profile", test::scene_path("cloud_fitted.json"), "--frames", "2", "--width", "48",
                                 "--height", "32", "--json"});
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_EQ(test::last_json_line(p.out)["particles"]["live"].get<size_t>(), in_file);
}

TEST(PyroCliCounts, DrawnSplatsAreCountedWhicheverDeviceOrdersThem) {
  const fs::path dir = test::scratch_dir("counts_devices");
  size_t drawn[2] = {0, 0};
  const char* devices[2] = {"cpu", "gpu"};
  for (int d = 0; d < 2; ++d) {
    const auto r = test::run_pyro({"render", test::scene_path("clouds.json"), "--out", (dir / devices[d]).string(),
                                   "--width", "48", "--height", "32", "--sort-device", devices[d], "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    drawn[d] = test::last_json_line(r.out)["drawn_particles"].get<size_t>();
  }
  EXPECT_GT(drawn[0], 0u);
  EXPECT_EQ(drawn[1], drawn[0]);
}

}  // namespace
}  // namespace pyro
