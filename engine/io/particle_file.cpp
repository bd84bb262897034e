#include "engine/io/particle_file.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"

namespace pyro {

namespace {
constexpr char kMagic[8] = {'P', 'Y', 'R', 'O', 'P', 'T', 'C', 'L'};
constexpr uint32_t kVersion = 1;
constexpr size_t kHeader = 28;
static_assert(std::endian::native == std::endian::little, "particle files are little-endian");
}  // namespace

void check_particles(const std::string& path, const std::vector<GaussianParticle>& particles) {
  for (size_t i = 0; i < particles.size(); ++i) {
    const GaussianParticle& p = particles[i];
    const float v[8] = {p.x, p.y, p.z, p.radius, p.density, p.r, p.g, p.b};
    bool ok = p.radius > 0.0f && p.density >= 0.0f && p.density <= 1.0f;
    for (float x : v) ok = ok && std::isfinite(x);
    if (!ok)
      throw UserError(path, "particle " + std::to_string(i),
                      "finite values, radius > 0 and density in [0, 1]");
  }
}

void write_particle_file(const std::string& path, const ParticleFile& file) {
  check_particles(path, file.particles);  // never a file that read_particle_file refuses
  DurableFile out(path);
  const uint32_t version = kVersion, record = sizeof(GaussianParticle);
  const uint64_t count = file.particles.size();
  const uint32_t meta = static_cast<uint32_t>(file.metadata_json.size());
  out.write(kMagic, 8);
  out.write(&version, 4);
  out.write(&record, 4);
  out.write(&count, 8);
  out.write(&meta, 4);
  out.write(file.metadata_json);
  out.write(file.particles.data(), count * sizeof(GaussianParticle));
  out.commit();
}

ParticleFile read_particle_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw UserError(path, "", "cannot open particle file: No such file or directory");
  const uint64_t size = static_cast<uint64_t>(in.tellg());
  in.seekg(0);
  char head[kHeader];
  if (size < kHeader || !in.read(head, kHeader))
    throw UserError(path, "", "a particle file (.pyrop), found a file shorter than its 28-byte header");
  if (std::memcmp(head, kMagic, 8) != 0)
    throw UserError(path, "", "a particle file starting with \"PYROPTCL\", found other bytes");
  uint32_t version, record, meta;
  uint64_t count;
  std::memcpy(&version, head + 8, 4);
  std::memcpy(&record, head + 12, 4);
  std::memcpy(&count, head + 16, 8);
  std::memcpy(&meta, head + 24, 4);
  if (version != kVersion)
    throw UserError(path, "", "particle file version 1, found " + std::to_string(version));
  if (record != sizeof(GaussianParticle))
    throw UserError(path, "", "32 bytes per particle, found " + std::to_string(record));
  if (count > (size - kHeader) / sizeof(GaussianParticle) ||
      kHeader + uint64_t(meta) + count * sizeof(GaussianParticle) != size)
    throw UserError(path, "", "a file of " + std::to_string(kHeader + uint64_t(meta) + count * 32) +
                                  " bytes for its " + std::to_string(count) +
                                  " particles, found " + std::to_string(size) + " (truncated?)");
  ParticleFile f;
  f.metadata_json.resize(meta);
  f.particles.resize(count);
  in.read(f.metadata_json.data(), meta);
  in.read(reinterpret_cast<char*>(f.particles.data()), static_cast<std::streamsize>(count * 32));
  if (!in) throw UserError(path, "", "cannot read the particle file");
  check_particles(path, f.particles);
  return f;
}

}  // namespace pyro
