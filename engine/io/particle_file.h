#pragma once
// Particle files (`.pyrop`): Gaussian particles made by `pyro import-vdb`, referenced by scenes.
// Layout (all little-endian; documented in docs/particle_format.md):
//   offset 0   8 bytes   magic "PYROPTCL"
//   offset 8   uint32    format version: 1 (isotropic particles) or 2 (anisotropic particles)
//   offset 12  uint32    bytes per particle (32 in version 1, 56 in version 2)
//   offset 16  uint64    particle count N
//   offset 24  uint32    metadata length M
//   offset 28  M bytes   metadata: a UTF-8 JSON object (source file, grid, error, ...)
//   then, version 1: N x 8 float32: x, y, z, radius, density, r, g, b
//                    (engine/particles/gaussian_particle.h)
//         version 2: N x 14 float32: centre x, y, z, rotation w, x, y, z, scale x, y, z,
//                    extinction, r, g, b (engine/particles/anisotropic_gaussian.h)
//   A record one float32 longer (36 bytes in version 1, 60 in version 2) carries the particle's
//   temperature last: the temperature grid's density-weighted mean over the particle, in the
//   grid's units (systems/runtime/cloud_import/gaussian_temperature.h), which a scene maps to kelvin.
// The file size must be exactly 28 + M + N times the record size. Written durably
// (engine/io/durable_file.h), so a reader never sees half a file.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/particles/anisotropic_gaussian.h"
#include "engine/particles/gaussian_particle.h"

namespace pyro {

struct ParticleFile {
  std::string metadata_json = "{}";
  // At most one of the two holds particles: a file is of one kind.
  std::vector<GaussianParticle> particles;        // version 1
  std::vector<AnisotropicGaussian> anisotropic;   // version 2
  // Empty, or one temperature per particle (either kind): written as the records' last field.
  std::vector<float> temperature;
  // As read: 1 or 2. For writing, 0 picks the version from the particles (2 when `anisotropic`
  // holds any, else 1); 1 or 2 asks for that version (so an empty file keeps its version).
  uint32_t version = 0;
};

// The bytes of one anisotropic particle in a version 2 file.
inline constexpr uint32_t kAnisotropicRecordBytes = 14 * 4;

// The reader's check of every particle: finite values, radius > 0, density in [0, 1]. Throws
// UserError(path, "particle I", ...) at the first one that fails.
void check_particles(const std::string& path, const std::vector<GaussianParticle>& particles);
// The same for anisotropic particles: finite values, every scale > 0, extinction >= 0 and a
// non-zero rotation quaternion (it is normalised where it is used).
void check_particles(const std::string& path, const std::vector<AnisotropicGaussian>& particles);

// The temperatures' check: finite, magnitude at most kMaxParticleTemperature. Throws
// UserError(path, "particle I", ...) at the first one that fails.
inline constexpr float kMaxParticleTemperature = 1e6f;
void check_temperatures(const std::string& path, const std::vector<float>& temperature);

// Checks the particles (check_particles: nothing is written that the reader would refuse) and
// that the file is of one kind, then writes it. Throws UserError or IoError
// (engine/io/io_error.h) naming the file.
void write_particle_file(const std::string& path, const ParticleFile& file);

// Throws UserError(path, "", why) for a missing, truncated or malformed file, and
// UserError(path, "particle I", why) for a value check_particles refuses.
ParticleFile read_particle_file(const std::string& path);

// The albedo of the medium the particles were imported from, which a lit scene relights them
// with (their colours hold the import's lighting): the metadata's "albedo" (pyro import-vdb
// writes it), else kImportAlbedoBeforeRecorded. Throws UserError(path, "metadata", why) when the
// metadata is not a JSON object or its "albedo" is not a number in [0, 1].
double imported_albedo(const std::string& path, const ParticleFile& file);
// What the import recorded of the particles' temperatures (metadata "temperature", written by
// pyro import-vdb beside a temperature channel): the grid, its largest value, the automatic
// map from its values to kelvin the import chose and the intensity it exposed the fire at. nullopt
// when the metadata has none. Throws UserError(path, "metadata/temperature", why) when it is not an
// object of finite numbers, or its intensity is negative.
struct RecordedTemperature {
  std::string grid;
  double max = 0.0;                 // the grid's largest value (resampled to the density)
  double scale = 1.0, offset = 0.0; // kelvin = scale * value + offset
  double intensity = 4.0;           // files written before the exposure was chosen all used 4
};
std::optional<RecordedTemperature> recorded_temperature(const std::string& path, const ParticleFile& file);

// Every import written without an "albedo" was made with this one (the importer's default medium).
inline constexpr double kImportAlbedoBeforeRecorded = 0.9;

}  // namespace pyro
