#include "tools/export/column_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace pyro {

namespace {

// One measured line: along axis `axis`, through world coordinates (u, v) on the two others.
struct Line {
  int axis = 0;
  double u = 0.0, v = 0.0;
};

// The grid's column depth: voxel times the sum over the planes of the bilinear lookup at (u, v).
double grid_depth(const MediaVoxels& g, const Line& l) {
  const VoxelBox& b = g.box;
  const int a = l.axis, ua = (a + 1) % 3, va = (a + 2) % 3;
  const double fu = l.u / b.voxel - b.origin[ua], fv = l.v / b.voxel - b.origin[va];
  const int iu = int(std::floor(fu)), iv = int(std::floor(fv));
  const double tu = fu - iu, tv = fv - iv;
  double sum = 0.0;
  for (int w = 0; w < b.dims[a]; ++w)
    for (int k = 0; k < 4; ++k) {
      std::array<int, 3> p{};
      p[a] = w;
      p[ua] = iu + (k & 1);
      p[va] = iv + (k >> 1);
      if (p[ua] < 0 || p[va] < 0 || p[ua] >= b.dims[ua] || p[va] >= b.dims[va]) continue;
      const double weight = (k & 1 ? tu : 1.0 - tu) * (k >> 1 ? tv : 1.0 - tv);
      sum += weight * g.density[b.at(p[0], p[1], p[2])];
    }
  return sum * b.voxel;
}

// The particles' exact column depth along the whole line.
double particle_depth(const std::vector<MediaSample>& samples, const Line& l) {
  glm::dvec3 o(0.0), w(0.0);
  o[(l.axis + 1) % 3] = l.u;
  o[(l.axis + 2) % 3] = l.v;
  w[l.axis] = 1.0;
  const double inf = std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (const MediaSample& s : samples) {
    const double reach = sample_reach(s);
    if (std::abs(s.field.c[(l.axis + 1) % 3] - l.u) > reach || std::abs(s.field.c[(l.axis + 2) % 3] - l.v) > reach)
      continue;
    sum += caster_optical_depth(s.field, o, w, -inf, inf);
  }
  return sum;
}

std::vector<Line> draw_lines(const std::vector<MediaSample>& samples, const VoxelBox& b, int per_axis, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Line> lines;
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < per_axis; ++i) {
      Line l;
      l.axis = a;
      const int ua = (a + 1) % 3, va = (a + 2) % 3;
      if (i % 2 == 0) {
        const MediaSample& s = samples[std::min(size_t(unit(rng) * double(samples.size())), samples.size() - 1)];
        l.u = s.field.c[ua] + (unit(rng) * 4.0 - 2.0) * s.detail;
        l.v = s.field.c[va] + (unit(rng) * 4.0 - 2.0) * s.detail;
      } else {
        l.u = (b.origin[ua] + unit(rng) * (b.dims[ua] - 1)) * b.voxel;
        l.v = (b.origin[va] + unit(rng) * (b.dims[va] - 1)) * b.voxel;
      }
      lines.push_back(l);
    }
  return lines;
}

}  // namespace

ColumnError measure_column_error(const std::vector<MediaSample>& samples, const MediaVoxels& grid, int lines_per_axis,
                                 uint64_t seed) {
  ColumnError e;
  if (samples.empty() || grid.box.voxels() == 0) return e;
  const std::vector<Line> lines = draw_lines(samples, grid.box, lines_per_axis, seed);
  std::vector<double> grid_tau(lines.size()), particle_tau(lines.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, lines.size()), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) {
      grid_tau[i] = grid_depth(grid, lines[i]);
      particle_tau[i] = particle_depth(samples, lines[i]);
    }
  });
  double squares = 0.0;
  for (size_t i = 0; i < lines.size(); ++i) {
    const double d = std::abs(std::exp(-grid_tau[i]) - std::exp(-particle_tau[i]));
    e.opacity_max = std::max(e.opacity_max, d);
    squares += d * d;
    e.depth_max = std::max(e.depth_max, std::abs(grid_tau[i] - particle_tau[i]));
    e.depth_peak = std::max(e.depth_peak, particle_tau[i]);
  }
  e.lines = int(lines.size());
  e.opacity_rms = std::sqrt(squares / double(lines.size()));
  return e;
}

}  // namespace pyro
