#include "systems/runtime/cloud_import/gaussian_lighting.h"

#include <algorithm>
#include <cmath>

#include "systems/runtime/cloud_import/gaussian_field.h"

namespace pyro {

using namespace gaussian_field;

namespace {

// -rho T over the grid's box (no margin: T is known only there).
std::vector<float> negative_lit_density(const DenseGrid& grid, const std::vector<float>& transmittance) {
  std::vector<float> r(grid.values.size());
  for (size_t q = 0; q < r.size(); ++q) r[q] = -grid.values[q] * transmittance[q];
  return r;
}

// The Gaussians' density sum f and the lit residual r = sum peak e lit - rho T.
void lit_fields(const DenseGrid& grid, const std::vector<GridGaussian>& gs, const std::vector<float>& transmittance,
                int threads, std::vector<float>& f, std::vector<float>& r) {
  const FieldBox box = field_box(grid, 0);
  f.assign(box.size(), 0.0f);
  add_gaussians(f, gs, box, threads, [](uint32_t) { return 1.0f; });
  r = negative_lit_density(grid, transmittance);
  add_gaussians(r, gs, box, threads, [&](uint32_t i) { return gs[i].lit; });
}

double lit_rmse(const DenseGrid& grid, const std::vector<float>& r) {
  double sum = 0.0;
  uint64_t n = 0;
  for (size_t q = 0; q < r.size(); ++q)
    if (grid.values[q] != 0.0f) {
      sum += double(r[q]) * r[q];
      ++n;
    }
  return n ? std::sqrt(sum / double(n)) : 0.0;
}

}  // namespace

std::vector<float> light_transmittance_field(const DenseGrid& grid, std::vector<float> t) {
  for (size_t q = 0; q < t.size(); ++q) t[q] = grid.values[q] != 0.0f ? std::exp(-t[q]) : 1.0f;
  return t;
}

double fit_lit_fractions(const DenseGrid& grid, std::vector<GridGaussian>& gs, const std::vector<float>& transmittance,
                         int iterations, int threads) {
  const FieldBox box = field_box(grid, 0);
  parallel_rows(int(gs.size()), threads, [&](int i) {
    double wsum = 0.0, tsum = 0.0;
    visit(gs[i], box, [&](size_t q, const glm::vec3&, const glm::vec3&, float e) {
      const double w = double(e) * grid.values[q];
      wsum += w;
      tsum += w * transmittance[q];
    });
    gs[i].lit = wsum > 0.0 ? float(tsum / wsum) : 1.0f;
  });
  std::vector<float> f, r;
  for (int it = 0; it < iterations; ++it) {
    lit_fields(grid, gs, transmittance, threads, f, r);
    parallel_rows(int(gs.size()), threads, [&](int i) {
      double num = 0.0, den = 0.0;
      visit(gs[i], box, [&](size_t q, const glm::vec3&, const glm::vec3&, float e) {
        num += double(e) * r[q];
        den += double(e) * f[q];
      });
      if (den > 0.0) gs[i].lit = float(std::clamp(double(gs[i].lit) - num / den, 0.0, 1.0));
    });
  }
  lit_fields(grid, gs, transmittance, threads, f, r);
  return lit_rmse(grid, r);
}

std::vector<double> lit_residual_shares(const DenseGrid& grid, const std::vector<GridGaussian>& gs,
                                        const std::vector<float>& transmittance, int threads) {
  std::vector<float> f, r;
  lit_fields(grid, gs, transmittance, threads, f, r);
  return shares_of(gs, field_box(grid, 0), r, f, threads);
}

std::vector<AnisotropicGaussian> lit_world_gaussians(const DenseGrid& grid, const std::vector<GridGaussian>& gs,
                                                     const VolumeMedium& medium) {
  std::vector<AnisotropicGaussian> out;
  out.reserve(gs.size());
  for (const GridGaussian& g : gs) {
    out.push_back(world_gaussian(grid, g, medium.extinction));
    // Not clamped to 1: a lit medium's source term exceeds 1 where light and ambient add up past
    // it (albedo 0.9, light 1, ambient 0.3), and the reference integrates it as it is.
    out.back().color = glm::vec3(glm::max(medium.albedo * (medium.light_color * double(g.lit) + medium.ambient),
                                          glm::dvec3(0.0)));
  }
  return out;
}

}  // namespace pyro
