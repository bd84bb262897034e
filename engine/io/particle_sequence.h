#pragma once
// Particle sequences (`NAME.pyroseq/`): an animated volume as a folder holding a manifest,
// `sequence.json`, and one ordinary particle file per source frame (engine/io/particle_file.h,
// written by write_particle_file), so a frame is read alone and whatever a particle file holds
// a sequence frame holds too. Documented in docs/particle_format.md.
//
// The manifest names every frame in ascending, consecutive source frame numbers, with its file,
// the file it was imported from and its particle count; the fps the source was simulated at; the
// medium (grid, extinction, albedo, error target); and the bounds of the particle centres over
// every frame, which scenes place the whole sequence by (one anchor, so it does not jump).
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/io/folder_output_kind.h"

namespace pyro {

inline constexpr const char* kParticleSequenceManifest = "sequence.json";
inline constexpr const char* kParticleSequenceFormat = "pyrocumulus particle sequence";
inline constexpr int kParticleSequenceVersion = 1;

// A sequence folder as an output: replaced whole by each import (folder_replacement.h).
inline FolderOutputKind particle_sequence_output_kind() {
  return {"particle sequence", {".partial-*"}, {"frame_*.pyrop", kParticleSequenceManifest}};
}

struct ParticleSequenceFrame {
  int64_t number = 0;          // the source frame number (from the source file's name)
  std::string file;            // the particle file, a plain name inside the sequence folder
  std::string source;          // the file it was imported from, as named on the command line
  uint64_t particles = 0;      // the particle file's count (checked when the frame is read)
  uint64_t active_voxels = 0;  // of the source grid
};

struct ParticleSequence {
  double fps = 24.0;           // source frames per second, > 0
  std::string grid;            // the grid imported from every frame
  double extinction = 0.0;     // per world unit per unit density, the same for every frame
  double albedo = 0.9;
  double error_target = 0.03;
  bool has_bounds = false;     // false when every frame is empty
  std::array<double, 3> bounds_min{0, 0, 0}, bounds_max{0, 0, 0};  // particle centres
  std::vector<ParticleSequenceFrame> frames;  // ascending, consecutive numbers; at least one

  // The most particles two consecutive frames hold together (a cross-fade draws both); with one
  // frame, its own count.
  uint64_t max_pair_particles() const;
};

// "frame_000042.pyrop" (negative numbers "frame_-00042.pyrop").
std::string particle_sequence_frame_name(int64_t number);

// The manifest's JSON text.
std::string particle_sequence_json(const ParticleSequence& sequence);

// Writes `folder`/sequence.json durably. Throws IoError.
void write_particle_sequence_manifest(const std::filesystem::path& folder, const ParticleSequence& sequence);

// Reads and checks `folder`/sequence.json: the format and version, every key's type and range,
// frames ascending and consecutive, each frame's file a plain name that exists as a regular file
// in the folder. Throws UserError(manifest path, JSON pointer, what was expected).
ParticleSequence read_particle_sequence(const std::string& folder);

// Whether `path` is a folder holding a sequence manifest.
bool is_particle_sequence(const std::string& path);

}  // namespace pyro
