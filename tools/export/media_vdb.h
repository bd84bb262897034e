#pragma once
// A frame's media voxels as the OpenVDB grids hosts read (written by engine/io/vdb_reader.h's
// write_vdb_grids, the one module that sees OpenVDB): "density", the extinction per world unit
// (a float fog volume, what Houdini's and Blender's volume shaders multiply by their density
// scale, 1 by default); "temperature" in kelvin, where the frame has fire; "color", linear RGB
// (vec3s), where the particles' colours differ; "emission", the radiance emitted per unit length
// (vec3s), when the voxels hold it (the Cycles comparison asks for it). Every grid has the voxels' transform (a uniform
// scale, index (0, 0, 0) at the world origin) and only the voxels with density.
#include <string>
#include <vector>

#include "engine/io/vdb_reader.h"
#include "tools/export/media_voxels.h"

namespace pyro {

std::vector<VdbGridToWrite> media_vdb_grids(const MediaVoxels& voxels);

}  // namespace pyro
