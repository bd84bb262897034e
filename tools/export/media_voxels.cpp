#include "tools/export/media_voxels.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace pyro {

namespace {

constexpr int kSlab = 4;  // z planes per task: each task owns its planes, so no two write one voxel

// The voxel index range [lo, hi] that `s`'s support covers on `box`, clipped to it.
bool index_span(const MediaSample& s, const VoxelBox& box, std::array<int, 3>& lo, std::array<int, 3>& hi) {
  const double reach = sample_reach(s);
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::max(int(std::ceil((s.field.c[a] - reach) / box.voxel)) - box.origin[a], 0);
    hi[a] = std::min(int(std::floor((s.field.c[a] + reach) / box.voxel)) - box.origin[a], box.dims[a] - 1);
    if (lo[a] > hi[a]) return false;
  }
  return true;
}

// The sample's extinction at voxel (x, y, z): the centre's, or a sphere's mean over 2^3 points.
double voxel_extinction(const MediaSample& s, const VoxelBox& box, int x, int y, int z) {
  const glm::dvec3 centre(double(box.origin[0] + x) * box.voxel, double(box.origin[1] + y) * box.voxel,
                          double(box.origin[2] + z) * box.voxel);
  // Away from a sphere's centre its field is smooth: the centre's value, as for the Gaussians.
  if (s.field.shape != CasterShape::sphere || glm::length(centre - s.field.c) > 1.5 * box.voxel)
    return extinction_at(s, centre);
  const double q = 0.25 * box.voxel;
  double sum = 0.0;
  for (int k = 0; k < 8; ++k)
    sum += extinction_at(s, centre + glm::dvec3(k & 1 ? q : -q, k & 2 ? q : -q, k & 4 ? q : -q));
  return sum / 8.0;
}

struct Accumulators {
  MediaVoxels& out;
  std::vector<float>& temperature_sum;
  std::vector<float>& color_sum;
  std::vector<float>& emission;
};

void add_sample(const MediaSample& s, const VoxelBox& box, int z0, int z1, Accumulators& acc) {
  std::array<int, 3> lo, hi;
  if (!index_span(s, box, lo, hi)) return;
  for (int z = std::max(lo[2], z0); z <= std::min(hi[2], z1); ++z)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int x = lo[0]; x <= hi[0]; ++x) {
        const float e = float(voxel_extinction(s, box, x, y, z));
        if (!(e > 0.0f)) continue;
        const size_t i = box.at(x, y, z);
        acc.out.density[i] += e;
        if (!acc.temperature_sum.empty()) acc.temperature_sum[i] += e * s.temperature;
        if (!acc.color_sum.empty())
          for (int c = 0; c < 3; ++c) acc.color_sum[3 * i + c] += e * s.color[c];
        if (!acc.emission.empty())
          for (int c = 0; c < 3; ++c) acc.emission[3 * i + c] += e * s.emission[c];
      }
}

// Weighted sums to means where there is density.
void finish_means(MediaVoxels& out, std::vector<float>& temperature_sum, std::vector<float>& color_sum) {
  for (size_t i = 0; i < out.density.size(); ++i) {
    const float d = out.density[i];
    if (!(d > 0.0f)) continue;
    if (!temperature_sum.empty()) temperature_sum[i] /= d;
    if (!color_sum.empty())
      for (int c = 0; c < 3; ++c) color_sum[3 * i + c] /= d;
  }
  out.temperature = std::move(temperature_sum);
  out.color = std::move(color_sum);
}

}  // namespace

VoxelBox media_box(const std::vector<MediaSample>& samples, double voxel) {
  VoxelBox box;
  box.voxel = voxel;
  if (samples.empty()) return box;
  std::array<int, 3> lo{std::numeric_limits<int>::max(), std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
  std::array<int, 3> hi{std::numeric_limits<int>::min(), std::numeric_limits<int>::min(), std::numeric_limits<int>::min()};
  for (const MediaSample& s : samples) {
    const double reach = sample_reach(s);
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], int(std::floor((s.field.c[a] - reach) / voxel)));
      hi[a] = std::max(hi[a], int(std::ceil((s.field.c[a] + reach) / voxel)));
    }
  }
  for (int a = 0; a < 3; ++a) {
    box.origin[a] = lo[a];
    box.dims[a] = hi[a] - lo[a] + 1;
  }
  return box;
}

MediaVoxels voxelize_media(const std::vector<MediaSample>& samples, const VoxelBox& box, const VoxelizeOptions& options) {
  MediaVoxels out;
  out.box = box;
  out.density.assign(box.voxels(), 0.0f);
  std::vector<float> temperature_sum(options.temperature ? box.voxels() : 0, 0.0f);
  std::vector<float> color_sum(options.color ? 3 * box.voxels() : 0, 0.0f);
  out.emission.assign(options.emission ? 3 * box.voxels() : 0, 0.0f);
  Accumulators acc{out, temperature_sum, color_sum, out.emission};
  const int slabs = (box.dims[2] + kSlab - 1) / kSlab;
  tbb::parallel_for(tbb::blocked_range<int>(0, slabs), [&](const tbb::blocked_range<int>& r) {
    for (int slab = r.begin(); slab != r.end(); ++slab) {
      const int z0 = slab * kSlab, z1 = std::min(z0 + kSlab, box.dims[2]) - 1;
      for (const MediaSample& s : samples) add_sample(s, box, z0, z1, acc);
    }
  });
  finish_means(out, temperature_sum, color_sum);
  return out;
}

}  // namespace pyro
