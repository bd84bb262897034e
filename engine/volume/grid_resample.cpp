#include "engine/volume/grid_resample.h"

#include <algorithm>
#include <cmath>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

namespace pyro {

double trilinear_at(const DenseGrid& grid, double x, double y, double z) {
  const double p[3] = {x, y, z};
  int base[3];
  double frac[3];
  for (int a = 0; a < 3; ++a) {
    if (!(p[a] > -1.0 && p[a] < grid.dims[a])) return 0.0;
    const double f = std::floor(p[a]);
    base[a] = int(f);
    frac[a] = p[a] - f;
  }
  double sum = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    int at[3];
    double weight = 1.0;
    for (int a = 0; a < 3; ++a) {
      const int step = (corner >> a) & 1;
      at[a] = base[a] + step;
      weight *= step ? frac[a] : 1.0 - frac[a];
    }
    const bool stored = at[0] >= 0 && at[1] >= 0 && at[2] >= 0 && at[0] < grid.dims[0] && at[1] < grid.dims[1] &&
                        at[2] < grid.dims[2];
    if (stored && weight > 0.0) sum += weight * grid.at(at[0], at[1], at[2]);
  }
  return sum;
}

DenseGrid resample_into(const DenseGrid& source, const GridHeader& target) {
  DenseGrid out;
  static_cast<GridHeader&>(out) = target;
  out.name = source.name;
  out.file = source.file;
  out.file_index = source.file_index;
  out.max_value = 0.0f;
  out.active_voxels = 0;
  out.values.assign(target.box_voxels(), 0.0f);
  if (source.empty() || out.values.empty()) return out;
  // Target local index -> world -> source local index.
  glm::dmat4 to_target_index(1.0), from_source_local(1.0);
  to_target_index[3] = glm::dvec4(target.origin[0], target.origin[1], target.origin[2], 1.0);
  from_source_local[3] = glm::dvec4(-source.origin[0], -source.origin[1], -source.origin[2], 1.0);
  const glm::dmat4 map = from_source_local * glm::inverse(source.index_to_world) * target.index_to_world * to_target_index;
  size_t k = 0;
  for (int z = 0; z < target.dims[2]; ++z)
    for (int y = 0; y < target.dims[1]; ++y)
      for (int x = 0; x < target.dims[0]; ++x, ++k) {
        const glm::dvec4 s = map * glm::dvec4(x, y, z, 1.0);
        const float v = float(trilinear_at(source, s.x, s.y, s.z));
        out.values[k] = v;
        out.max_value = std::max(out.max_value, v);
        out.active_voxels += v != 0.0f;
      }
  return out;
}

}  // namespace pyro
