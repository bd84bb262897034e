#pragma once
// Particle files (`.pyrop`): Gaussian particles made by `pyro import-vdb`, referenced by scenes.
// Layout (all little-endian; documented in docs/particle_format.md):
//   offset 0   8 bytes   magic "PYROPTCL"
//   offset 8   uint32    format version (1)
//   offset 12  uint32    bytes per particle (32)
//   offset 16  uint64    particle count N
//   offset 24  uint32    metadata length M
//   offset 28  M bytes   metadata: a UTF-8 JSON object (source file, grid, error, ...)
//   then       N x 8 float32: x, y, z, radius, density, r, g, b (engine/particles/gaussian_particle.h)
// The file size must be exactly 28 + M + 32 N. Written durably (engine/io/durable_file.h), so a
// reader never sees half a file.
#include <string>
#include <vector>

#include "engine/particles/gaussian_particle.h"

namespace pyro {

struct ParticleFile {
  std::string metadata_json = "{}";
  std::vector<GaussianParticle> particles;
};

// The reader's check of every particle: finite values, radius > 0, density in [0, 1]. Throws
// UserError(path, "particle I", ...) at the first one that fails.
void check_particles(const std::string& path, const std::vector<GaussianParticle>& particles);

// Checks the particles (check_particles: nothing is written that the reader would refuse), then
// writes the file. Throws UserError or IoError (engine/io/io_error.h) naming the file.
void write_particle_file(const std::string& path, const ParticleFile& file);

// Throws UserError(path, "", why) for a missing, truncated or malformed file or a non-finite value.
ParticleFile read_particle_file(const std::string& path);

}  // namespace pyro
