#pragma once
// Where a volume entity's particles came from (a scene's `volumes[]` entry): for reports. The
// particles themselves live in the entity's ParticleSet, fixed after loading.
#include <cstdint>
#include <string>

namespace pyro {

struct VolumeSource {
  std::string path;            // the file read (the entry's `file`, or its `fallback`)
  bool used_fallback = false;
  uint64_t active_voxels = 0;  // of the imported grid; 0 for a particle file
  uint64_t particles = 0;
};

}  // namespace pyro
