// A fire cache shown with the vdb template's defaults (content/templates/vdb.json, its file
// replaced) reads as fire: the exposure (systems/runtime/cloud_import/fire_exposure.h) keeps every
// pixel's largest channel within the display's range, where the fixed intensity 4 it replaces
// saturates a dense hot cache into a white disc, and its brightest pixel stays a flame's colour.
// A dense Mantaflow-like cache (a hot ball, normalised heat) written here, the project's own fire
// and the OpenUSD densityAndHeat file (shared data, skipped when absent).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/content_path.h"
#include "engine/io/vdb_reader.h"
#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/rendered_frame.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// A Mantaflow-like cache frame: a ball of smoke at full density, its heat 1 at the centre falling
// to 0.85 at its edge (a flame throughout), in a 32-voxel box.
std::string write_dense_hot_cache(const fs::path& dir) {
  const int n = 32;
  VdbGridToWrite density, heat;
  density.name = "density";
  heat.name = "heat";
  density.dims = heat.dims = {n, n, n};
  density.voxel_size = heat.voxel_size = {0.05, 0.05, 0.05};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double r = std::hypot(x - 15.5, y - 15.5, z - 15.5) / 12.0;
        density.values.push_back(r < 1.0 ? 1.0f : 0.0f);
        heat.values.push_back(r < 1.0 ? float(1.0 - 0.15 * r * r) : 0.0f);
      }
  const std::string path = (dir / "fluid_data_0001.vdb").string();
  write_vdb_grids(path, {density, heat});
  return path;
}

// The vdb template drawing `vdb`, with `emission` (JSON, empty: the template's own: none).
RgbImage template_frame(const fs::path& dir, const std::string& vdb, const std::string& emission) {
  std::ifstream in(content_path("templates/vdb.json"));
  nlohmann::json scene = nlohmann::json::parse(in);
  scene.erase("$schema");
  scene["volumes"][0]["file"] = vdb;
  if (!emission.empty()) scene["volumes"][0]["emission"] = nlohmann::json::parse(emission);
  const std::string path = (dir / "vdb_template.json").string();
  std::ofstream(path) << scene.dump();
  const SceneDescription s = load_scene(path);
  return test::rendered_frame(s, s.width, s.height);
}

struct FrameLook {
  int clipped = 0;           // pixels whose largest channel exceeds 1 (shown rolled off)
  glm::dvec3 brightest{0.0};  // the pixel of largest red (the fire's)
};

FrameLook look(const RgbImage& image) {
  FrameLook l;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* c = image.at(x, y);
      if (std::max({c[0], c[1], c[2]}) > 1.0f) ++l.clipped;
      if (c[0] > l.brightest.x) l.brightest = glm::dvec3(c[0], c[1], c[2]);
    }
  return l;
}

TEST(FireExposureFrame, ADenseHotCacheReadsAsFireWhereAFixedIntensitySaturatesIt) {
  const fs::path dir = test::scratch_dir("fire_exposure_dense");
  const std::string vdb = write_dense_hot_cache(dir);
  const FrameLook fixed = look(template_frame(dir, vdb, R"({"intensity": 4})"));
  const FrameLook exposed = look(template_frame(dir, vdb, ""));
  EXPECT_GT(fixed.clipped, 500) << "the fixed intensity no longer saturates the cache: the test shows nothing";
  EXPECT_EQ(exposed.clipped, 0);
  // A flame's colour: red over green over blue, not a white disc.
  EXPECT_GT(exposed.brightest.x, 0.3);
  EXPECT_GT(exposed.brightest.x, 1.3 * exposed.brightest.y);
  EXPECT_GT(exposed.brightest.y, exposed.brightest.z);
}

TEST(FireExposureFrame, TheProjectsFireAndTheOpenUsdCacheClipNoPixel) {
  const fs::path dir = test::scratch_dir("fire_exposure_files");
  EXPECT_EQ(look(template_frame(dir, content_path("volumes/sample_fire.vdb"), "")).clipped, 0);
  const fs::path usd = fs::path(PYRO_SHARED_DATA_DIR) / "vdb" / "openusd_densityAndHeat.vdb";
  if (!fs::exists(usd)) GTEST_SKIP() << "no third-party VDB file at " << usd.string() << " (optional data)";
  EXPECT_EQ(look(template_frame(dir, usd.string(), "")).clipped, 0);
}

}  // namespace
}  // namespace pyro
