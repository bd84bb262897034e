#pragma once
// A scene's `volumes[]` entry naming a particle sequence (a `.pyroseq` folder), made into the
// VolumeSequence component that plays it: the manifest read and checked, the playback keys
// (start_frame, loop, speed) checked against it, and one placement for every frame from the
// bounds of all the frames' particles (so the volume does not jump from frame to frame).
#include <cstdint>

#include "components/volume_sequence.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

struct SequenceAsset {
  VolumeSequence sequence;
  uint64_t capacity = 0;        // the most particles one drawn frame holds (two frames cross-faded)
  uint64_t active_voxels = 0;   // the most of one source frame
};

// `scene` as resolved (its fps is the runtime clock's). Throws UserError(scene file, entry pointer + "/file", why) when the manifest cannot be used, and
// UserError(scene file, entry pointer + "/start_frame", ...) for a start frame outside the
// sequence.
SequenceAsset load_sequence_asset(const SceneDescription& scene, const VolumeDescription& volume);

}  // namespace pyro
