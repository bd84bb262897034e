#include "engine/io/particle_file.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"

namespace pyro {

namespace {
constexpr char kMagic[8] = {'P', 'Y', 'R', 'O', 'P', 'T', 'C', 'L'};
constexpr uint32_t kIsotropicVersion = 1, kAnisotropicVersion = 2;
constexpr size_t kHeader = 28;
static_assert(std::endian::native == std::endian::little, "particle files are little-endian");

// A version 2 record, in the file's order.
using AnisotropicRecord = float[14];

void to_record(const AnisotropicGaussian& g, float* r) {
  const float v[14] = {g.centre.x,   g.centre.y,   g.centre.z,   g.rotation.w, g.rotation.x,
                       g.rotation.y, g.rotation.z, g.scale.x,    g.scale.y,    g.scale.z,
                       g.extinction, g.color.x,    g.color.y,    g.color.z};
  std::memcpy(r, v, sizeof v);
}

AnisotropicGaussian from_record(const float* r) {
  AnisotropicGaussian g;
  g.centre = {r[0], r[1], r[2]};
  g.rotation = glm::quat(r[3], r[4], r[5], r[6]);
  g.scale = {r[7], r[8], r[9]};
  g.extinction = r[10];
  g.color = {r[11], r[12], r[13]};
  return g;
}

uint32_t version_to_write(const std::string& path, const ParticleFile& file) {
  if (!file.particles.empty() && !file.anisotropic.empty())
    throw UserError(path, "", "particles of one kind (isotropic or anisotropic), found both");
  if (file.version == 0) return file.anisotropic.empty() ? kIsotropicVersion : kAnisotropicVersion;
  if (file.version == kIsotropicVersion && file.anisotropic.empty()) return kIsotropicVersion;
  if (file.version == kAnisotropicVersion && file.particles.empty()) return kAnisotropicVersion;
  throw UserError(path, "", "version 1 for isotropic particles or 2 for anisotropic ones, asked for " +
                                std::to_string(file.version) + " with the other kind");
}

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

void check_particles(const std::string& path, const std::vector<AnisotropicGaussian>& particles) {
  for (size_t i = 0; i < particles.size(); ++i) {
    const AnisotropicGaussian& g = particles[i];
    float v[14];
    to_record(g, v);
    bool ok = g.scale.x > 0.0f && g.scale.y > 0.0f && g.scale.z > 0.0f && g.extinction >= 0.0f;
    for (float x : v) ok = ok && std::isfinite(x);
    // In double, so that no finite non-zero float quaternion underflows to length 0.
    const double q2 = double(g.rotation.w) * g.rotation.w + double(g.rotation.x) * g.rotation.x +
                      double(g.rotation.y) * g.rotation.y + double(g.rotation.z) * g.rotation.z;
    if (!ok || !(q2 > 0.0))
      throw UserError(path, "particle " + std::to_string(i),
                      "finite values, scales > 0, extinction >= 0 and a non-zero rotation quaternion");
  }
}

void check_temperatures(const std::string& path, const std::vector<float>& temperature) {
  for (size_t i = 0; i < temperature.size(); ++i)
    if (!(std::abs(temperature[i]) <= kMaxParticleTemperature))
      throw UserError(path, "particle " + std::to_string(i),
                      "a finite temperature of magnitude at most 1e6, found " + std::to_string(temperature[i]));
}

namespace {

// The particles' records, `fields` float32 each (the temperature last when there is one).
std::vector<float> records_of(const ParticleFile& file, bool aniso, size_t fields) {
  const size_t count = aniso ? file.anisotropic.size() : file.particles.size();
  std::vector<float> records(fields * count);
  for (size_t i = 0; i < count; ++i) {
    float* r = &records[fields * i];
    if (aniso) {
      to_record(file.anisotropic[i], r);
    } else {
      const GaussianParticle& p = file.particles[i];
      const float v[8] = {p.x, p.y, p.z, p.radius, p.density, p.r, p.g, p.b};
      std::memcpy(r, v, sizeof v);
    }
    if (!file.temperature.empty()) r[fields - 1] = file.temperature[i];
  }
  return records;
}

}  // namespace

void write_particle_file(const std::string& path, const ParticleFile& file) {
  const uint32_t version = version_to_write(path, file);
  check_particles(path, file.particles);  // never a file that read_particle_file refuses
  check_particles(path, file.anisotropic);
  check_temperatures(path, file.temperature);
  const bool aniso = version == kAnisotropicVersion;
  const uint64_t count = aniso ? file.anisotropic.size() : file.particles.size();
  if (!file.temperature.empty() && file.temperature.size() != count)
    throw UserError(path, "", "one temperature per particle (" + std::to_string(count) + "), given " +
                                  std::to_string(file.temperature.size()));
  const size_t fields = (aniso ? 14 : 8) + (file.temperature.empty() ? 0 : 1);
  DurableFile out(path);
  const uint32_t record = uint32_t(fields * sizeof(float));
  const uint32_t meta = static_cast<uint32_t>(file.metadata_json.size());
  out.write(kMagic, 8);
  out.write(&version, 4);
  out.write(&record, 4);
  out.write(&count, 8);
  out.write(&meta, 4);
  out.write(file.metadata_json);
  const std::vector<float> records = records_of(file, aniso, fields);
  out.write(records.data(), records.size() * sizeof(float));
  out.commit();
}

namespace {

struct Header {
  uint32_t version, record, meta;
  uint64_t count;
};

Header read_header(const std::string& path, std::ifstream& in, uint64_t size) {
  char head[kHeader];
  if (size < kHeader || !in.read(head, kHeader))
    throw UserError(path, "", "a particle file (.pyrop), found a file shorter than its 28-byte header");
  if (std::memcmp(head, kMagic, 8) != 0)
    throw UserError(path, "", "a particle file starting with \"PYROPTCL\", found other bytes");
  Header h;
  std::memcpy(&h.version, head + 8, 4);
  std::memcpy(&h.record, head + 12, 4);
  std::memcpy(&h.count, head + 16, 8);
  std::memcpy(&h.meta, head + 24, 4);
  if (h.version != kIsotropicVersion && h.version != kAnisotropicVersion)
    throw UserError(path, "", "particle file version 1 or 2, found " + std::to_string(h.version));
  const uint32_t plain = h.version == kIsotropicVersion ? 32 : kAnisotropicRecordBytes;
  const uint32_t want = h.record == plain + 4 ? plain + 4 : plain;
  if (h.record != want)
    throw UserError(path, "", std::to_string(plain) + " bytes per particle in version " + std::to_string(h.version) +
                                  " (or " + std::to_string(plain + 4) + " with a temperature), found " +
                                  std::to_string(h.record));
  if (h.count > (size - kHeader) / want || kHeader + uint64_t(h.meta) + h.count * want != size)
    throw UserError(path, "", "a file of " + std::to_string(kHeader + uint64_t(h.meta) + h.count * want) +
                                  " bytes for its " + std::to_string(h.count) +
                                  " particles, found " + std::to_string(size) + " (truncated?)");
  return h;
}

}  // namespace

ParticleFile read_particle_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw UserError(path, "", "cannot open particle file: No such file or directory");
  const uint64_t size = static_cast<uint64_t>(in.tellg());
  in.seekg(0);
  const Header h = read_header(path, in, size);
  ParticleFile f;
  f.version = h.version;
  f.metadata_json.resize(h.meta);
  in.read(f.metadata_json.data(), h.meta);
  const size_t fields = h.record / 4;
  const bool with_temperature = h.record == (h.version == kIsotropicVersion ? 32u : kAnisotropicRecordBytes) + 4;
  std::vector<float> records(fields * h.count);
  in.read(reinterpret_cast<char*>(records.data()), static_cast<std::streamsize>(h.count * h.record));
  if (!in) throw UserError(path, "", "cannot read the particle file");
  if (h.version == kIsotropicVersion) f.particles.resize(h.count);
  else f.anisotropic.resize(h.count);
  if (with_temperature) f.temperature.resize(h.count);
  for (size_t i = 0; i < h.count; ++i) {
    const float* r = &records[fields * i];
    if (h.version == kIsotropicVersion) f.particles[i] = {r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]};
    else f.anisotropic[i] = from_record(r);
    if (with_temperature) f.temperature[i] = r[fields - 1];
  }
  check_particles(path, f.particles);
  check_particles(path, f.anisotropic);
  check_temperatures(path, f.temperature);
  return f;
}

double imported_albedo(const std::string& path, const ParticleFile& file) {
  const nlohmann::json meta = nlohmann::json::parse(file.metadata_json, nullptr, false);
  if (!meta.is_object()) throw UserError(path, "metadata", "a JSON object");
  const auto albedo = meta.find("albedo");
  if (albedo == meta.end()) return kImportAlbedoBeforeRecorded;
  if (!albedo->is_number() || !(albedo->get<double>() >= 0.0 && albedo->get<double>() <= 1.0))
    throw UserError(path, "metadata/albedo", "a number in [0, 1], found " + albedo->dump());
  return albedo->get<double>();
}

std::optional<RecordedTemperature> recorded_temperature(const std::string& path, const ParticleFile& file) {
  const nlohmann::json meta = nlohmann::json::parse(file.metadata_json, nullptr, false);
  if (!meta.is_object()) throw UserError(path, "metadata", "a JSON object");
  const auto t = meta.find("temperature");
  if (t == meta.end() || t->is_null()) return std::nullopt;
  const auto number = [&](const char* key, double fallback) {
    const auto v = t->find(key);
    if (v == t->end()) return fallback;
    if (!v->is_number() || !std::isfinite(v->get<double>()))
      throw UserError(path, std::string("metadata/temperature/") + key, "a finite number, found " + v->dump());
    return v->get<double>();
  };
  if (!t->is_object()) throw UserError(path, "metadata/temperature", "a JSON object, found " + t->dump());
  RecordedTemperature r;
  const auto grid = t->find("grid");
  if (grid != t->end() && grid->is_string()) r.grid = grid->get<std::string>();
  r.max = number("max", 0.0);
  r.scale = number("scale", 1.0);
  r.offset = number("offset", 0.0);
  r.intensity = number("intensity", r.intensity);
  if (r.intensity < 0.0)
    throw UserError(path, "metadata/temperature/intensity", "a number at least 0, found " + t->at("intensity").dump());
  return r;
}

}  // namespace pyro
