#pragma once
// A fire's emission beside a density grid, for the CPU volume reference (volume_reference.h): the
// temperature grid in the density's index space (engine/volume/grid_resample.h) and how its
// values become emitted radiance (engine/math/temperature_emission.h). The reference's source
// term gains L_e(T(p)), T reconstructed trilinearly at the sample point p like the density.
#include "engine/math/temperature_emission.h"
#include "engine/volume/dense_grid.h"

namespace pyro {

struct VolumeEmission {
  DenseGrid temperature;  // same box and layout as the density grid; empty: no emission
  TemperatureEmission emission;
  bool on() const { return !temperature.empty() && emission.table.size > 0; }
};

}  // namespace pyro
