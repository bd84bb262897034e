#pragma once
// The volume_sequence system: plays every particle sequence (components/volume_sequence.h) into
// its entity's ParticleSet at the current scene time (sequence_clock.h, sequence_frames.h).
//
// It runs first in the light phase, not in the simulate phase: the frames that a ranged render
// (`--frames A:B`) only simulates never draw a sequence, so they read none of its frames, and the
// frames that draw it fill it from the clock alone, so a range draws exactly what a full run
// draws. The light phase's systems that read particles run after it
// (order_after_volume_sequence).
#include <vector>

#include "engine/ecs/schedule.h"

namespace pyro {

inline constexpr const char* kVolumeSequenceSystem = "volume_sequence";

ecs::SystemDesc volume_sequence_system();

// Makes every system of `systems` in the light phase whose access conflicts with the
// volume_sequence system's run after it (it must come before them in `systems`).
void order_after_volume_sequence(std::vector<ecs::SystemDesc>& systems);

}  // namespace pyro
