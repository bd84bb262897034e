#pragma once
// Looking at an imported grid without a scene: the camera that frames its bounding box and the
// default medium (what `pyro import-vdb`, `pyro bench vdb` and the import's error measurement
// render it with).
#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"
#include "engine/math/camera_math.h"
#include "systems/scene/scene_description.h"

namespace pyro {

// Looks at the centre of the grid's world bounds from the +z side, a little above and to the
// right, far enough that the bounding sphere fits the vertical field of view (45 degrees).
CameraDescription framing_camera(const DenseGrid& grid);
CameraFrame camera_frame(const CameraDescription& c, int width, int height);
VolumeMedium default_medium(const DenseGrid& grid);

}  // namespace pyro
