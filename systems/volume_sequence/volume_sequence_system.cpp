#include "systems/volume_sequence/volume_sequence_system.h"

#include "components/frame_clock.h"
#include "components/particle_set.h"
#include "components/volume_sequence.h"
#include "engine/ecs/world.h"
#include "systems/volume_sequence/sequence_frames.h"

namespace pyro {

namespace {

void play_sequences(ecs::World& world) {
  const FrameClock& clock = world.resource<const FrameClock>();
  world.each<VolumeSequence, ParticleSet>([&](ecs::Entity, VolumeSequence& s, ParticleSet& set) {
    const double position = sequence_position(clock.frame, s.runtime_frames_per_second, s.frames_per_second, s.start);
    fill_sequence_particles(s, sample_sequence(position, s.frames.size(), s.loop), set.pool);
  });
}

}  // namespace

ecs::SystemDesc volume_sequence_system() {
  return {.name = kVolumeSequenceSystem,
          .phase = ecs::Phase::light,
          .access = ecs::Access::of<ecs::Reads<FrameClock>, ecs::Writes<VolumeSequence, ParticleSet>>(),
          .run = play_sequences};
}

void order_after_volume_sequence(std::vector<ecs::SystemDesc>& systems) {
  const ecs::SystemDesc playback = volume_sequence_system();
  bool seen = false;
  for (ecs::SystemDesc& d : systems) {
    if (d.name == playback.name) {
      seen = true;
      continue;
    }
    if (seen && d.phase == ecs::Phase::light && d.access.conflicts_with(playback.access))
      d.after.push_back(playback.name);
  }
}

}  // namespace pyro
