#include "systems/volume_sequence/sequence_asset.h"

#include <algorithm>
#include <filesystem>

#include "engine/core/user_error.h"
#include "engine/io/particle_sequence.h"

namespace pyro {

namespace {

ParticleSequence read_manifest(const SceneDescription& scene, const VolumeDescription& v) {
  try {
    return read_particle_sequence(v.path);
  } catch (const UserError& e) {
    throw UserError(scene.file, v.pointer + (v.used_fallback ? "/fallback" : "/file"),
                    std::string("cannot use particle sequence: ") + e.what());
  }
}

std::size_t start_index(const SceneDescription& scene, const VolumeDescription& v, const ParticleSequence& m) {
  if (!v.sequence.has_start_frame) return 0;
  const int64_t first = m.frames.front().number, last = m.frames.back().number;
  if (v.sequence.start_frame < first || v.sequence.start_frame > last)
    throw UserError(scene.file, v.pointer + "/start_frame",
                    "a frame of the sequence \"" + v.path + "\", in [" + std::to_string(first) + ", " +
                        std::to_string(last) + "], found " + std::to_string(v.sequence.start_frame));
  return std::size_t(v.sequence.start_frame - first);
}

// p' = position + scale (p - anchor), from the bounds of every frame's particle centres.
void place(VolumeSequence& s, const VolumeDescription& v, const ParticleSequence& m) {
  const glm::dvec3 lo(m.bounds_min[0], m.bounds_min[1], m.bounds_min[2]);
  const glm::dvec3 hi(m.bounds_max[0], m.bounds_max[1], m.bounds_max[2]);
  s.anchor = v.anchor_center && m.has_bounds ? 0.5 * (lo + hi) : glm::dvec3(0.0);
  s.scale = v.scale;
  if (v.size > 0.0f) {
    const glm::dvec3 extent = hi - lo;
    const double longest = std::max({extent.x, extent.y, extent.z});
    s.scale = m.has_bounds && longest > 0.0 ? double(v.size) / longest : 1.0;
  }
  s.at = glm::dvec3(v.position);
}

}  // namespace

SequenceAsset load_sequence_asset(const SceneDescription& scene, const VolumeDescription& v) {
  const ParticleSequence m = read_manifest(scene, v);
  SequenceAsset out;
  VolumeSequence& s = out.sequence;
  s.folder = v.path;
  for (const ParticleSequenceFrame& f : m.frames) {
    s.frames.push_back({(std::filesystem::path(v.path) / f.file).string(), f.particles});
    out.active_voxels = std::max(out.active_voxels, f.active_voxels);
  }
  s.frames_per_second = m.fps * double(v.sequence.speed);
  s.runtime_frames_per_second = double(scene.frames_per_second);  // the clock's dt is 1 / this
  s.start = start_index(scene, v, m);
  s.loop = v.sequence.loop;
  place(s, v, m);
  s.use_albedo = scene.shadows.has_value();
  s.albedo = float(m.albedo);
  out.capacity = m.max_pair_particles();
  return out;
}

}  // namespace pyro
