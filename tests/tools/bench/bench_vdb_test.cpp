// pyro bench vdb against OpenVDB's own renderer: on a generated soft ball, the CPU reference and
// vdb_render (an independent implementation of the same single-scattering model, run as a
// separate program) agree closely once both see the same scene (no ambient light, black
// behind), closer still as vdb_render's steps shrink, and the splats are scored against it. Skipped, saying why, where
// vdb_render is not installed (Debian's libopenvdb-tools; tools/install-deps.sh installs it).
#include "tools/bench/bench_vdb.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "engine/io/vdb_reader.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(BenchVdb, TheReferenceAgreesWithVdbRenderAndTheSplatsAreScored) {
  if (std::system("command -v vdb_render > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "vdb_render is not on PATH (Debian's libopenvdb-tools): nothing to compare with";
  const auto dir = test::scratch_dir("bench_vdb_ball");
  const std::string path = (dir / "ball.vdb").string();
  const int n = 24;
  std::vector<float> v(size_t(n) * n * n);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double c = 0.5 * (n - 1);
        const double d2 = (x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c);
        v[(size_t(z) * n + y) * n + x] = d2 < 100.0 ? float(1.0 - d2 / 100.0) : 0.0f;
      }
  write_vdb_fog_volume(path, "density", {0, 0, 0}, {n, n, n}, v, 0.1, {0, 0, 0});
  VdbBenchOptions o;
  o.file = path;
  o.width = 96;
  o.height = 96;
  const nlohmann::json coarse = bench_vdb(o);  // vdb_render's default-like steps (0.5, 1 voxel)
  o.vdb_render_step = o.vdb_render_shadow_step = 0.1;
  const nlohmann::json fine = bench_vdb(o);
  ASSERT_FALSE(coarse["rmse_vs_vdb_render"].is_null()) << coarse.dump();
  ASSERT_FALSE(fine["rmse_vs_vdb_render"].is_null()) << fine.dump();
  const double at_coarse = coarse["rmse_vs_vdb_render"]["reference"];
  const double at_fine = fine["rmse_vs_vdb_render"]["reference"];
  // Two renderers of one model: they agree, and closer as vdb_render's quadrature refines.
  EXPECT_LT(at_fine, 0.01) << fine.dump();
  EXPECT_LT(at_fine, 0.75 * at_coarse) << coarse.dump() << fine.dump();
  EXPECT_LT(fine["rmse_vs_vdb_render"]["splats"].get<double>(), 0.05) << fine.dump();
  EXPECT_GT(coarse["vdb_render_ms"].get<double>(), 0.0);
}

}  // namespace
}  // namespace pyro
