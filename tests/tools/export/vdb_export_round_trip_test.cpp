// The export's round trip (tools/export/vdb_round_trip.h): a small cloud scene's frame exported,
// the file read back and ray marched, and imported again as the engine imports a .vdb on load;
// each drawn by the CPU reference as an opacity image (white media over black: each pixel its
// ray's 1 - exp(-tau)) against the original particles'. The grid differs by at most the export's
// stated error (its column opacity target) anywhere in the image; the re-imported particles by
// at most the export's error plus the import's target in RMSE (the import's target is an RMSE).
// An export at voxels as large as a particle's radius misses both bounds: the test can fail.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/test_paths.h"
#include "tools/export/vdb_round_trip.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

constexpr double kRoundTripExportError = 0.01;
constexpr double kRoundTripImportError = 0.01;
// The ray marcher's own error (a tenth of a voxel a step, midpoint rule) and the lines the
// export measured being axis-aligned while the camera's rays are not.
constexpr double kRoundTripMarchSlack = 0.003;

const char* kRoundTripCloud = R"({
  "name": "round_trip", "seed": 7, "output": {"width": 64, "height": 48},
  "camera": {"position": [0, 0.3, 6], "target": [0, 0, 0], "fov_y_deg": 40},
  "clouds": [{"count": 60, "radius": 0.5, "density": 0.4, "color": [0.9, 0.8, 0.7],
              "box": {"min": [-1.2, -0.6, -0.8], "max": [1.2, 0.6, 0.8]}}]
})";

nlohmann::json round_trip_of_cloud(const std::string& scratch, double voxel_size) {
  const fs::path dir = test::scratch_dir(scratch);
  VdbRoundTripOptions o;
  o.scene = (dir / "cloud.json").string();
  std::ofstream(o.scene) << kRoundTripCloud;
  o.error = kRoundTripExportError;
  o.import_error = kRoundTripImportError;
  o.voxel_size = voxel_size;
  o.width = 96;
  o.height = 72;
  const VdbRoundTrip r = measure_vdb_round_trip(o, nullptr);
  std::printf("%s", r.text.c_str());
  return r.json;
}

TEST(ExportVdbRoundTrip, ImportedFrameRendersWithinTheStatedError) {
  const nlohmann::json j = round_trip_of_cloud("export_vdb_round_trip", 0.0);
  EXPECT_TRUE(j["export"]["error_met"].get<bool>());
  EXPECT_LE(j["grid_opacity_max_difference"].get<double>(), kRoundTripExportError + kRoundTripMarchSlack);
  EXPECT_LE(j["opacity_rmse"].get<double>(), kRoundTripExportError + kRoundTripImportError);
  EXPECT_GT(j["grid_opacity_max_difference"].get<double>(), 0.0);
}

TEST(ExportVdbRoundTrip, ACoarseGridMissesTheBound) {
  const nlohmann::json j = round_trip_of_cloud("export_vdb_round_trip_coarse", 0.5);
  EXPECT_FALSE(j["export"]["error_met"].get<bool>());
  EXPECT_GT(j["grid_opacity_max_difference"].get<double>(), kRoundTripExportError + kRoundTripMarchSlack);
  EXPECT_GT(j["opacity_rmse"].get<double>(), kRoundTripExportError + kRoundTripImportError);
}

}  // namespace
}  // namespace pyro
