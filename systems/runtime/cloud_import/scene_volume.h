#pragma once
// A scene's `volumes[]` entry made into Gaussian particles: a particle file is read as it is
// (isotropic particles from a version 1 file, anisotropic ones from a version 2 file), an
// OpenVDB grid is imported (cloud_import.h) with the scene's light, then the placement
// (position, scale or size, anchor; systems/runtime/scene/scene_description.h) is applied.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/particles/particle_pool.h"

#include "engine/particles/anisotropic_gaussian.h"
#include "engine/particles/gaussian_particle.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

struct SceneVolume {
  std::vector<GaussianParticle> particles;
  std::vector<AnisotropicGaussian> anisotropic;  // a version 2 particle file's (then `particles`
                                                 // is empty)
  uint64_t active_voxels = 0;  // of the imported grid (0 for a particle file)
  std::string grid;            // the grid imported (empty for a particle file)
  std::string note;            // the reader's note when the grid was chosen by default
  std::string fire_note;       // which temperature grid and map made the volume's fire (empty: none)
};

// Throws UserError(scene file, entry pointer + "/file" or "/fallback", why) when the file cannot
// be read or holds no usable grid; the message names the volume file. `threads` as in
// CloudImportOptions (0: hardware concurrency).
SceneVolume load_scene_volume(const SceneDescription& scene, const VolumeDescription& volume,
                              int threads = 0);

// p' = position + s (p - anchor), radius' = s radius; opacities stay: placement is a change of
// units, so a volume looks the same at any size (set `extinction` to change how dense it looks).
// The particles as a pool (exactly sized) that the sorting and billboard systems draw.
ParticlePool to_particle_pool(const std::vector<GaussianParticle>& particles);

void place_volume_particles(std::vector<GaussianParticle>& particles, const VolumeDescription& volume);
// The same for anisotropic particles: centres placed alike, scales times s, extinction over s (so
// optical depths, and opacities, stay).
void place_volume_particles(std::vector<AnisotropicGaussian>& particles, const VolumeDescription& volume);

}  // namespace pyro
