#pragma once
// Per-scene resource limits (the scene's optional `budget` object, docs/scene_format.md) and the
// check that refuses a scene over them before anything is allocated: particles (clouds +
// emitters' pool capacities + volume particles), estimated memory (particle storage and draw
// lists, plus render targets for width x height x views) and texture size.
#include <cstdint>
#include <string>

#include "components/render_modes.h"

namespace pyro {

struct SceneDescription;

// Defaults chosen for the build machine (24 GiB RAM, 2 cores, llvmpipe): 20 M particles render
// at a few seconds a frame there, and 4 GiB leaves room for the driver and the OS.
struct SceneBudget {
  uint64_t particles = 20'000'000;        // 1 .. 4,000,000,000
  uint64_t memory_bytes = 4ull << 30;     // scene key memory_mib: 1 .. 1,048,576 (1 TiB)
  int texture_size = 0;                   // largest target side; 0: the driver's maximum
};

// Estimated bytes per particle: the structure-of-arrays pool (16 floats, a byte, a 32-bit id:
// engine/particles/particle_pool.h), the sort's working space (a 16-byte key, its 8-byte pair
// and swap pair, a 32-bit index), and per view the draw list and the GPU's copy in a ring of two
// slots that grow by half again (systems/billboard_render): for Gaussian splats an index in the
// list and 32 bytes of particle and the index on the GPU; for the other shapes the particles
// packed once (48 bytes) and per view three vec4s in the list and four on the GPU.
uint64_t particle_bytes_estimate(int views, ParticleShape shape = ParticleShape::gaussian);
// Estimated render-target bytes per pixel and view: four RGBA16F colour + 32-bit depth targets
// (opaque scene, particle layer, media layers, composition).
inline constexpr uint64_t kTargetBytesPerPixelPerView = 4 * (8 + 4);

struct SceneCost {
  uint64_t particles = 0;
  uint64_t memory_bytes = 0;
  int texture_size = 0;  // the largest side of any target
};

// What the scene will hold at width x height per view with `views` views (1 mono, 2 stereo),
// `output_width` the widest target (2 x width side by side), plus `volume_particles` already
// read from the scene's volumes.
SceneCost estimate_scene_cost(const SceneDescription& scene, int width, int height, int views,
                              int output_width, uint64_t volume_particles);

// Throws UserError(scene.file, "/budget/...", ...) with the numbers when `cost` exceeds the
// scene's budget; `driver_max_texture` stands for texture_size 0.
void check_scene_budget(const SceneDescription& scene, const SceneCost& cost, int driver_max_texture);

}  // namespace pyro
