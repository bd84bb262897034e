#pragma once
// The temperature grid of a VDB file, beside its density grid: which one (named, found by its
// usual names, or none), read and carried into the density grid's index space
// (engine/volume/grid_resample.h), so that a fire's temperature is indexed like its density
// whatever the two grids' transforms, voxel sizes and boxes.
#include <optional>
#include <string>
#include <vector>

#include "engine/io/vdb_reader.h"
#include "engine/volume/dense_grid.h"

namespace pyro {

// The names looked for, in this order, when none is given: Houdini's and Blender's `temperature`,
// Mantaflow's `heat`, then Mantaflow's `flame`.
inline const std::vector<std::string> kTemperatureGridNames = {"temperature", "heat", "flame"};

// `requested`: empty picks the first float grid named in kTemperatureGridNames (none: nullopt);
// "none" turns temperature off (nullopt); any other name must be a float grid of the file.
// Throws UserError(path, place, why) naming the option or key `place`, what was asked and the
// grids the file holds when a named grid is absent or not a float grid.
std::optional<VdbGridInfo> choose_temperature_grid(const std::string& path, const std::vector<VdbGridInfo>& grids,
                                                   const std::string& requested, const std::string& place);

// The chosen grid read (engine/io/vdb_reader.h, read_vdb_grid: values checked there) and
// resampled into `density`'s index space.
DenseGrid read_temperature_grid(const std::string& path, const VdbGridInfo& grid, const GridHeader& density);

}  // namespace pyro
