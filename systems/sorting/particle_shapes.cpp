#include "systems/sorting/particle_shapes.h"

#include "components/particle_kind.h"
#include "components/particle_set.h"

namespace pyro {

ParticleShape particle_shape_of(const ecs::World& world, ecs::Entity entity, ParticleShape scene_wide) {
  const ParticleKind* kind = world.try_get<const ParticleKind>(entity);
  return kind ? kind->shape : scene_wide;
}

std::optional<ParticleShape> common_particle_shape(const ecs::World& world, ParticleShape scene_wide) {
  std::optional<ParticleShape> common;
  bool mixed = false;
  world.each<const ParticleSet>([&](ecs::Entity e, const ParticleSet&) {
    const ParticleShape shape = particle_shape_of(world, e, scene_wide);
    if (common && *common != shape) mixed = true;
    common = shape;
  });
  if (mixed) return std::nullopt;
  return common.value_or(scene_wide);
}

}  // namespace pyro
