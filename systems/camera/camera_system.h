#pragma once
// Camera phase, the `stereo_camera` system: turns the first Camera entity (and its
// StereoCamera, if any) into this frame's View: the mono frame and the frames of the eyes that
// are rendered. The only place eye frames are made; sorting and rendering read them from View.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc stereo_camera_system();

}  // namespace pyro
