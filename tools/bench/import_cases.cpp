#include "tools/bench/import_cases.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

#include "tools/import/fitted_import.h"
#include "tools/import/vdb_import_evaluation.h"

namespace pyro {

namespace {

// A grid of n^3 voxels (index = world) whose voxel (x, y, z) holds density(x, y, z).
DenseGrid grid_of(int n, const std::function<float(double, double, double)>& density) {
  DenseGrid g;
  g.dims = {n, n, n};
  g.values.resize(size_t(n) * n * n);
  g.index_to_world = glm::dmat4(1.0);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const float v = density(x, y, z);
        g.values[(size_t(z) * n + y) * n + x] = v;
        g.active_voxels += v > 0.0f;
        g.max_value = std::max(g.max_value, v);
      }
  return g;
}

// Smooth value noise in [0, 1] on a lattice of `cell` voxels (hashed corners, smoothstep blend).
double value_noise(double x, double y, double z, double cell) {
  auto hash = [](int64_t i, int64_t j, int64_t k) {
    uint64_t h = uint64_t(i) * 0x9E3779B97F4A7C15ull ^ uint64_t(j) * 0xC2B2AE3D27D4EB4Full ^
                 uint64_t(k) * 0x165667B19E3779F9ull;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return double(h >> 11) * 0x1p-53;
  };
  x /= cell, y /= cell, z /= cell;
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  auto s = [](double t) { return t * t * (3.0 - 2.0 * t); };
  const double u = s(x - fx), v = s(y - fy), w = s(z - fz);
  double sum = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
    sum += (dx ? u : 1 - u) * (dy ? v : 1 - v) * (dz ? w : 1 - w) *
           hash(int64_t(fx) + dx, int64_t(fy) + dy, int64_t(fz) + dz);
  }
  return sum;
}

}  // namespace

std::vector<ImportCase> import_cases(double scale) {
  const auto side = [&](int n) { return std::max(8, int(std::lround(n * scale))); };
  std::vector<ImportCase> cases;
  {  // a box of 21^3 voxels of density 1 with a margin of 4 empty voxels: edges and corners
    const int n = side(29), lo = side(29) / 2 - side(21) / 2, hi = lo + side(21);
    cases.push_back({"box", grid_of(n, [&](double x, double y, double z) {
                       return x >= lo && x < hi && y >= lo && y < hi && z >= lo && z < hi ? 1.0f : 0.0f;
                     })});
  }
  {  // a torus shell: the wall of a tube (radius 3 voxels around a circle of radius 12), 1.5 thick
    const int n = side(36);
    const double c = 0.5 * (n - 1), major = 12.0 * scale, minor = 3.0 * scale;
    cases.push_back({"torus shell", grid_of(n, [&](double x, double y, double z) {
                       const double ring = std::hypot(x - c, z - c) - major;
                       const double tube = std::hypot(ring, y - c);
                       return std::abs(tube - minor) < 0.75 ? 1.0f : 0.0f;
                     })});
  }
  {  // a uniform sphere of radius 12 voxels, density 0.5, hard-edged
    const int n = side(30);
    const double c = 0.5 * (n - 1), r = 12.0 * scale;
    cases.push_back({"uniform sphere", grid_of(n, [&](double x, double y, double z) {
                       return (x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c) < r * r ? 0.5f : 0.0f;
                     })});
  }
  {  // a noise cloud: two octaves of value noise, thresholded, in a soft ball
    const int n = side(40);
    const double c = 0.5 * (n - 1);
    cases.push_back({"noise cloud", grid_of(n, [&](double x, double y, double z) {
                       const double ball = 1.0 - std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c)) / c;
                       const double noise = 0.65 * value_noise(x, y, z, 8 * scale) + 0.35 * value_noise(x, y, z, 3 * scale);
                       return float(std::clamp((noise - 0.45) * 3.0 * std::max(ball, 0.0) * 2.0, 0.0, 1.0));
                     })});
  }
  {  // a sheet two voxels thick across the grid
    const int n = side(32), mid = n / 2;
    cases.push_back({"sheet", grid_of(n, [&](double, double y, double) {
                       return y == mid - 1 || y == mid ? 1.0f : 0.0f;
                     })});
  }
  return cases;
}

nlohmann::json bench_import_cases(const ImportCasesOptions& o) {
  const std::vector<ImportCase> cases = import_cases(o.scale);
  ProgressTask progress(o.progress, "bench import-cases", cases.size() * o.error_targets.size());
  size_t done = 0;
  nlohmann::json rows = nlohmann::json::array();
  for (const ImportCase& c : cases) {
    const VdbImportReference reference = make_vdb_import_reference(c.grid, o.width, o.height, true);
    nlohmann::json targets = nlohmann::json::array();
    for (double error : o.error_targets) {
      progress.stage(done, c.name);
      const FittedImport fit = import_to_target(c.grid, error, reference);
      const VdbImportResult& r = fit.best;
      nlohmann::json t = {{"error", error},
                          {"particles", r.report.particles},
                          {"particles_per_voxel", double(r.report.particles) / double(c.grid.active_voxels)},
                          {"rmse_views_mean", r.rmse_views_mean},
                          {"rmse_views_max", r.rmse_views_max},
                          {"rmse_inside", std::isfinite(r.rmse_inside) ? nlohmann::json(r.rmse_inside) : nlohmann::json(nullptr)},
                          {"target_met", fit.target_met},
                          {"refinements", fit.refinements}};
      if (!fit.target_met) t["reason"] = fit.reason;
      targets.push_back(t);
      progress.update(++done);
    }
    rows.push_back({{"name", c.name}, {"active_voxels", c.grid.active_voxels}, {"targets", targets}});
  }
  return {{"width", o.width}, {"height", o.height}, {"cases", rows}};
}

}  // namespace pyro
