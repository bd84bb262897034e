#pragma once
// Entity handles: an index into the world's slot table plus the generation the slot had when
// the handle was made. Destroying an entity bumps its slot's generation before the index is
// recycled, so an old handle never aliases the slot's next occupant: it is simply dead.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace pyro::ecs {

struct Entity {
  // Default-constructed handles are null, so a forgotten initialisation can never name a
  // live entity.
  uint32_t index = UINT32_MAX;
  uint32_t generation = UINT32_MAX;

  static const Entity null;

  friend constexpr bool operator==(Entity, Entity) = default;
  constexpr bool is_null() const { return index == UINT32_MAX && generation == UINT32_MAX; }
};

// Defined out of line because Entity is incomplete inside its own body.
inline constexpr Entity Entity::null{UINT32_MAX, UINT32_MAX};
inline constexpr Entity null_entity = Entity::null;

// "12v3" = index 12, generation 3; used in error messages.
inline std::string to_string(Entity e) {
  if (e.is_null()) return "null";
  return std::to_string(e.index) + "v" + std::to_string(e.generation);
}

}  // namespace pyro::ecs

template <>
struct std::hash<pyro::ecs::Entity> {
  std::size_t operator()(pyro::ecs::Entity e) const noexcept {
    // Pack both halves into 64 bits and mix, so handles differing only in generation spread.
    uint64_t k = (uint64_t(e.generation) << 32) | e.index;
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    return std::size_t(k);
  }
};
