#include "systems/volume_sequence/sequence_frames.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"

namespace pyro {

namespace {

std::vector<GaussianParticle> read_frame(const VolumeSequence& s, std::size_t index) {
  const SequenceFrameFile& f = s.frames[index];
  ParticleFile file = read_particle_file(f.path);
  if (!file.anisotropic.empty())
    throw UserError(f.path, "", "isotropic particles (a version 1 particle file) in a sequence frame, found " +
                                    std::to_string(file.anisotropic.size()) + " anisotropic ones");
  if (file.particles.size() != f.particles)
    throw UserError(f.path, "", std::to_string(f.particles) + " particles, as the sequence's manifest says, found " +
                                    std::to_string(file.particles.size()));
  for (GaussianParticle& p : file.particles) {
    const glm::dvec3 q = s.at + s.scale * (glm::dvec3(p.x, p.y, p.z) - s.anchor);
    p.x = float(q.x);
    p.y = float(q.y);
    p.z = float(q.z);
    p.radius = float(s.scale * p.radius);
    if (s.use_albedo) p.r = p.g = p.b = s.albedo;
  }
  return std::move(file.particles);
}

void append(ParticlePool& pool, const std::vector<GaussianParticle>& particles, double weight) {
  if (pool.size() + particles.size() > pool.capacity())
    throw std::length_error("sequence frame of " + std::to_string(particles.size()) +
                            " particles does not fit the volume's pool of " + std::to_string(pool.capacity()));
  for (const GaussianParticle& p : particles) {
    ParticleInit init;
    init.position = {p.x, p.y, p.z};
    init.radius = p.radius;
    init.density = faded_density(p.density, weight);
    init.color = {p.r, p.g, p.b};
    pool.spawn(init);
  }
}

}  // namespace

float faded_density(float density, double weight) {
  if (weight >= 1.0) return density;
  if (weight <= 0.0) return 0.0f;
  return float(1.0 - std::pow(1.0 - double(density), weight));
}

const LoadedSequenceFrame& sequence_frame(VolumeSequence& s, std::size_t index) {
  for (LoadedSequenceFrame& f : s.loaded)
    if (f.index == index) {
      f.last_used = s.steps;
      return f;
    }
  if (s.loaded.size() >= std::max<std::size_t>(s.window, 2)) {
    const auto oldest = std::min_element(s.loaded.begin(), s.loaded.end(), [](const auto& x, const auto& y) {
      return x.last_used < y.last_used;
    });
    s.loaded.erase(oldest);
  }
  s.loaded.push_back({index, read_frame(s, index), s.steps});
  s.reads.push_back(index);
  return s.loaded.back();
}

void fill_sequence_particles(VolumeSequence& s, const SequenceSample& sample, ParticlePool& pool) {
  s.steps += 1;
  pool.clear();
  append(pool, sequence_frame(s, sample.a).particles, 1.0 - sample.weight);
  // Frame a stays in the window while b is read: the window holds at least two frames.
  if (sample.weight > 0.0 && sample.b != sample.a) append(pool, sequence_frame(s, sample.b).particles, sample.weight);
  for (std::size_t i = 0; i < pool.size(); ++i) pool.id[i] = uint32_t(i);
  s.frame_a = sample.a;
  s.frame_b = sample.b;
  s.weight = sample.weight;
}

}  // namespace pyro
