#pragma once
// Resource: every light of the frame in one block laid out as the GPU reads it (std140), written
// by the light phase (systems/lighting/light_block.h) and bound by every renderer at binding
// kLightBlockBinding; content/shaders/lights.glsl declares the same block. Positions and
// directions are in world space.
#include <cstddef>

#include <glm/vec4.hpp>

#include "components/fire_lights.h"

namespace pyro {

// The most directional lights a scene may hold (the scene loader refuses more).
inline constexpr int kMaxSuns = 16;
// The uniform-buffer binding point of the block in every program (lights.glsl).
inline constexpr unsigned kLightBlockBinding = 0;

struct LightBlock {
  glm::vec4 ambient{0.0f};  // rgb: the ambient term
  glm::ivec4 counts{0};     // x: suns, y: fire lights
  glm::vec4 sun_toward[kMaxSuns]{};    // xyz: unit, toward the light (0 for a sun of no direction)
  glm::vec4 sun_travel[kMaxSuns]{};    // xyz: the way it travels as the scene gives it (not unit)
  glm::vec4 sun_radiance[kMaxSuns]{};  // rgb: colour times intensity
  glm::vec4 fire_position[kMaxFireLights]{};   // xyz: the point light's place; w: its radius
  glm::vec4 fire_intensity[kMaxFireLights]{};  // rgb: intensity per steradian
};

// std140 puts each member at the offset of the C++ layout: vec4s and ivec4s, arrays of vec4.
static_assert(offsetof(LightBlock, counts) == 16 && offsetof(LightBlock, sun_toward) == 32);
static_assert(offsetof(LightBlock, sun_travel) == 32 + 16 * kMaxSuns);
static_assert(offsetof(LightBlock, sun_radiance) == 32 + 32 * kMaxSuns);
static_assert(offsetof(LightBlock, fire_position) == 32 + 48 * kMaxSuns);
static_assert(sizeof(LightBlock) == 32 + 48 * kMaxSuns + 32 * kMaxFireLights);

}  // namespace pyro
