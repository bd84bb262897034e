#pragma once
// Looking at an imported grid without a scene: the camera that frames its bounding box and the
// default medium (what `pyro import-vdb`, `pyro bench vdb` and the import's error measurement
// render it with).
#include <optional>
#include <vector>

#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

// Looks at the centre of the grid's world bounds from the +z side, a little above and to the
// right, far enough that the bounding sphere fits the vertical field of view (45 degrees).
// Takes the header alone: dense and sparse grids are framed alike.
CameraDescription framing_camera(const GridHeader& grid);
// The framing camera, then six more at its distance looking at the centre from +x, -x, +y, -y,
// +z and -z: views from every side.
std::vector<CameraDescription> views_around(const GridHeader& grid);
// A camera inside the volume, when its bounds are at least 8 voxels on every side: at the centre,
// looking along +x with a 90-degree field of view.
std::optional<CameraDescription> view_inside(const DenseGrid& grid);
CameraFrame camera_frame(const CameraDescription& c, int width, int height);
VolumeMedium default_medium(const GridHeader& grid);

}  // namespace pyro
