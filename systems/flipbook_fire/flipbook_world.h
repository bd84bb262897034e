#pragma once
// Flipbook fires into a world, in two steps. load_flipbooks reads each fire's folder (resolved:
// the runtime's asset step names the engine's baked flipbook where the scene named none) and
// prepares its frames (crop, black base line, softened base); fires that use the same folder
// with the same preparation share one set of frames. add_flipbook_fires uploads those frames to
// the FlipbookRenderer resource (made on first use) and makes one entity per fire with its
// billboards expanded (flipbook_layout.h). A bad folder or frame throws UserError naming it.
#include <cstddef>
#include <functional>
#include <vector>

#include "components/flipbook_fire.h"
#include "engine/ecs/world.h"
#include "systems/flipbook_fire/flipbook_folder.h"

namespace pyro {

struct FlipbookAssets {
  std::vector<FlipbookFrames> frames;  // prepared, in the order the fires first use them
  std::vector<size_t> fire_frames;     // per fire: its index into `frames`
};

// A fire's frames, read from its folder and prepared.
FlipbookFrames read_prepared_flipbook(const FlipbookFire& fire);

// Every fire's `flipbook` must name a folder (not be empty). `prepared` gives the frames of a
// fire whose folder and preparation no earlier fire had (read_prepared_flipbook, or a cache).
FlipbookAssets load_flipbooks(const std::vector<FlipbookFire>& fires,
                              const std::function<FlipbookFrames(const FlipbookFire&)>& prepared =
                                  read_prepared_flipbook);

void add_flipbook_fires(ecs::World& world, const std::vector<FlipbookFire>& fires,
                        const FlipbookAssets& assets);

}  // namespace pyro
