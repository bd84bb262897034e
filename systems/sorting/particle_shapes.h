#pragma once
// What each ParticleSet is drawn as: its own kind (components/particle_kind.h) or the scene-wide
// one (RenderSettings::particles). The sorting system lists sets of different kinds in one
// back-to-front order with each entry's kind; the billboard system draws that order in runs.
#include <optional>

#include "components/render_modes.h"
#include "engine/ecs/world.h"

namespace pyro {

// The kind of the set at `entity`: its ParticleKind, else `scene_wide`.
ParticleShape particle_shape_of(const ecs::World& world, ecs::Entity entity, ParticleShape scene_wide);

// The one kind every ParticleSet of `world` is drawn as (no sets: `scene_wide`), or none when
// the sets' kinds differ (a mixed scene).
std::optional<ParticleShape> common_particle_shape(const ecs::World& world, ParticleShape scene_wide);

}  // namespace pyro
