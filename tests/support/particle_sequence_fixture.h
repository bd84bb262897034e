#pragma once
// Made-up particle sequences for tests: every frame an ordinary particle file written by the
// engine's writer, the manifest with the bounds of all the centres, as `pyro import-vdb` writes
// them.
#include <algorithm>
#include <filesystem>
#include <vector>

#include "engine/io/particle_file.h"
#include "engine/io/particle_sequence.h"

namespace pyro::test {

inline ParticleSequence write_test_sequence(const std::filesystem::path& folder,
                                            const std::vector<std::vector<GaussianParticle>>& frames, double fps,
                                            int64_t first_number = 1) {
  std::filesystem::create_directories(folder);
  ParticleSequence s;
  s.fps = fps;
  s.grid = "density";
  s.extinction = 1.0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const int64_t number = first_number + int64_t(i);
    ParticleFile f;
    f.version = 1;
    f.particles = frames[i];
    write_particle_file((folder / particle_sequence_frame_name(number)).string(), f);
    s.frames.push_back({number, particle_sequence_frame_name(number), "made up", frames[i].size(), 0});
    for (const GaussianParticle& p : frames[i]) {
      const std::array<double, 3> c{p.x, p.y, p.z};
      for (int k = 0; k < 3; ++k) {
        s.bounds_min[k] = s.has_bounds ? std::min(s.bounds_min[k], c[k]) : c[k];
        s.bounds_max[k] = s.has_bounds ? std::max(s.bounds_max[k], c[k]) : c[k];
      }
      s.has_bounds = true;
    }
  }
  write_particle_sequence_manifest(folder, s);
  return s;
}

inline GaussianParticle test_particle(float x, float y, float z, float radius, float density, float grey = 1.0f) {
  return {x, y, z, radius, density, grey, grey, grey};
}

}  // namespace pyro::test
