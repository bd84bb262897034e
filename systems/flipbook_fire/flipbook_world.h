#pragma once
// Builds the flipbook fires of a scene into a world: one entity per fire with its billboards
// expanded (flipbook_layout.h), its flipbook read from its folder (the engine's baked one when
// the scene names none, baked first if missing: flipbook_bake.h), prepared (crop, black base
// line, softened base) and uploaded to the FlipbookRenderer resource (made on first use). Fires
// that use the same folder with the same preparation share one texture. A bad folder or frame
// throws UserError naming it.
#include <vector>

#include "components/flipbook_fire.h"
#include "engine/ecs/world.h"

namespace pyro {

void add_flipbook_fires(ecs::World& world, const std::vector<FlipbookFire>& fires);

}  // namespace pyro
