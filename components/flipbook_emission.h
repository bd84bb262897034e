#pragma once
// What a flipbook fire (components/flipbook_fire.h) gives off as light, frame by frame: the mean
// linear radiance of each flame frame over its whole card, as the fire shader shows it (its sRGB
// texels made linear; with "linear-alpha" blending, times their alpha). A card of area A showing
// frame f at colour scale s is a light of intensity s A frame_radiance[f] (docs/lighting.md).
// Made when the fire's frames are loaded (systems/flipbook_fire/flipbook_world.h), beside the
// FlipbookFire on its entity.
#include <vector>

#include <glm/vec3.hpp>

namespace pyro {

struct FlipbookEmission {
  std::vector<glm::vec3> frame_radiance;  // per frame of the flipbook, in playing order
};

}  // namespace pyro
