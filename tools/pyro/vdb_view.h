#pragma once
// What `pyro import-vdb` and `pyro bench vdb` share: the default camera that frames a grid's
// bounding box, the default medium, and the error target's mapping to the importer's tolerance.
#include "components/volume_medium.h"
#include "systems/scene/scene_description.h"
#include "engine/io/vdb_reader.h"
#include "engine/math/camera_math.h"

namespace pyro::cli {

// Looks at the centre of the grid's world bounds from the +z side, a little above and to the
// right, far enough that the bounding sphere fits the vertical field of view (45 degrees).
CameraDescription framing_camera(const DenseGrid& grid);
CameraFrame camera_frame(const CameraDescription& c, int width, int height);
VolumeMedium default_medium(const DenseGrid& grid);

}  // namespace pyro::cli
