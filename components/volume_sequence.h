#pragma once
// An animated volume played from a particle sequence (engine/io/particle_sequence.h): which
// source frame shows at which scene time, where the frames are placed, and the small window of
// frames read so far. The volume_sequence system (systems/volume_sequence) fills the entity's
// ParticleSet from it every drawn frame: the two source frames around the current time,
// cross-faded.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/particles/gaussian_particle.h"

namespace pyro {

struct SequenceFrameFile {
  std::string path;        // the frame's particle file
  uint64_t particles = 0;  // as the manifest says (checked when read)
};

struct LoadedSequenceFrame {
  std::size_t index = 0;                     // into VolumeSequence::frames
  std::vector<GaussianParticle> particles;   // placed, coloured for the scene
  uint64_t last_used = 0;                    // the playback step that last drew it
};

struct VolumeSequence {
  std::string folder;
  std::vector<SequenceFrameFile> frames;  // in source frame order, consecutive numbers
  // Source frames per second of scene time (the manifest's fps times the scene's `speed`), and
  // the frame shown at scene time 0 (an index into `frames`).
  double frames_per_second = 24.0;
  std::size_t start = 0;
  // Runtime frames per second of scene time: the clock's 1 / dt (the scene's fps, times a quality
  // pick's substeps), kept exact here rather than taken from the float dt.
  double runtime_frames_per_second = 30.0;
  bool loop = false;
  // Placement, one for every frame: p' = at + scale (p - anchor), radius times scale.
  glm::dvec3 at{0.0}, anchor{0.0};
  double scale = 1.0;
  // A lit scene relights the particles from the medium's albedo (their colours hold the import's
  // light): when set, every particle's colour is `albedo`.
  bool use_albedo = false;
  float albedo = 0.9f;

  // The frames read and kept (at most `window`, the least recently drawn dropped first).
  std::size_t window = 3;
  std::vector<LoadedSequenceFrame> loaded;
  std::vector<std::size_t> reads;  // every frame index read from disk, in order
  uint64_t steps = 0;              // playback steps run
  // What the last step drew: frames a and b with weights 1 - weight and weight.
  std::size_t frame_a = 0, frame_b = 0;
  double weight = 0.0;
};

}  // namespace pyro
