#include "tools/export/voxel_size_choice.h"

#include <algorithm>
#include <cmath>

#include "tools/export/media_voxels.h"

namespace pyro {

namespace {

// The smallest voxel whose box over the samples holds at most max_voxels (bisection on a log scale).
double finest_fitting(const std::vector<MediaSample>& samples, double from, uint64_t max_voxels) {
  double lo = from, hi = from;
  while (media_box(samples, hi).voxels() > max_voxels) hi *= 2.0;
  if (hi == lo) return lo;
  for (int i = 0; i < 40; ++i) {
    const double mid = std::sqrt(lo * hi);
    (media_box(samples, mid).voxels() > max_voxels ? lo : hi) = mid;
  }
  return hi;
}

VoxelSizeChoice measure_at(const std::vector<MediaSample>& samples, double voxel, double error) {
  VoxelSizeChoice c;
  c.voxel = voxel;
  const MediaVoxels grid = voxelize_media(samples, media_box(samples, voxel));
  c.voxels = grid.box.voxels();
  c.error = measure_column_error(samples, grid);
  c.met = c.error.opacity_max <= error;
  return c;
}

}  // namespace

double finest_detail(const std::vector<MediaSample>& samples) {
  double d = 0.0;
  for (const MediaSample& s : samples)
    if (s.detail > 0.0 && (d == 0.0 || s.detail < d)) d = s.detail;
  return d;
}

VoxelSizeChoice choose_voxel_size(const std::vector<MediaSample>& samples, double error, uint64_t max_voxels,
                                  int max_tries) {
  VoxelSizeChoice best;
  if (samples.empty()) return best;
  const double floor_voxel = finest_fitting(samples, finest_detail(samples) * 1e-3, max_voxels);
  double voxel = std::max(finest_detail(samples), floor_voxel);
  VoxelSizeChoice finest;  // the finest measured, for a target never met
  int tries = 0;
  while (tries < max_tries) {
    VoxelSizeChoice now = measure_at(samples, voxel, error);
    ++tries;
    if (now.met && (!best.met || now.voxel > best.voxel)) best = now;
    if (tries == 1 || now.voxel < finest.voxel) finest = now;
    if (now.met && now.error.opacity_max > 0.5 * error) break;  // within a factor of two of the target
    const double scale = 0.9 * std::sqrt(error / std::max(now.error.opacity_max, 1e-12));
    double next = voxel * std::clamp(scale, 0.35, 2.0);
    if (best.met && next >= best.voxel * 2.0) next = best.voxel * 1.4;  // approach from below slowly
    if (next < floor_voxel) {
      if (voxel <= floor_voxel) break;  // the finest fitting grid was measured
      next = floor_voxel;
    }
    voxel = next;
  }
  VoxelSizeChoice& chosen = best.met ? best : finest;
  chosen.tries = tries;
  if (!best.met) chosen.fits = finest.voxel > floor_voxel * (1.0 + 1e-9);
  return chosen;
}

}  // namespace pyro
