#include "engine/io/particle_sequence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"

namespace pyro {

namespace {

using nlohmann::json;

// The manifest being read, for errors: the file and a JSON pointer.
struct ManifestReader {
  std::string file;
  [[noreturn]] void fail(const std::string& pointer, const std::string& expected) const {
    throw UserError(file, pointer, expected);
  }
  const json& require(const json& object, const std::string& pointer, const std::string& key,
                      const std::string& expected) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(pointer, "a key \"" + key + "\" (" + expected + "), found none");
    return *it;
  }
  double number(const json& object, const std::string& pointer, const std::string& key, double lo,
                bool lo_open, double hi) const {
    const json& v = require(object, pointer, key, "a number");
    const std::string range = std::string(lo_open ? "(" : "[") + format(lo) + ", " + format(hi) + "]";
    if (!v.is_number()) fail(pointer + "/" + key, "a number in " + range + ", found " + v.dump());
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < lo || (lo_open && x == lo) || x > hi)
      fail(pointer + "/" + key, "a number in " + range + ", found " + v.dump());
    return x;
  }
  int64_t integer(const json& object, const std::string& pointer, const std::string& key, int64_t lo,
                  int64_t hi) const {
    const json& v = require(object, pointer, key, "an integer");
    if (!v.is_number_integer() || v.get<int64_t>() < lo || v.get<int64_t>() > hi)
      fail(pointer + "/" + key, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                                    "], found " + v.dump());
    return v.get<int64_t>();
  }
  std::string string(const json& object, const std::string& pointer, const std::string& key) const {
    const json& v = require(object, pointer, key, "a string");
    if (!v.is_string()) fail(pointer + "/" + key, "a string, found " + v.dump());
    return v.get<std::string>();
  }
  std::array<double, 3> vec3(const json& object, const std::string& pointer, const std::string& key) const {
    const json& v = require(object, pointer, key, "an array of 3 numbers");
    if (!v.is_array() || v.size() != 3 || !std::all_of(v.begin(), v.end(), [](const json& x) {
          return x.is_number() && std::isfinite(x.get<double>());
        }))
      fail(pointer + "/" + key, "an array of 3 finite numbers, found " + v.dump());
    return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  }
  static std::string format(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
  }
};

json read_manifest_json(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw UserError(file, "", "a readable particle sequence manifest, found none");
  std::stringstream text;
  text << in.rdbuf();
  try {
    return json::parse(text.str());
  } catch (const json::parse_error& e) {
    throw UserError(file, "", std::string("a JSON object, found invalid JSON: ") + e.what());
  }
}

ParticleSequenceFrame read_frame(const ManifestReader& r, const json& f, const std::string& pointer,
                                 const std::filesystem::path& folder) {
  if (!f.is_object()) r.fail(pointer, "an object describing a frame, found " + f.dump());
  ParticleSequenceFrame frame;
  frame.number = r.integer(f, pointer, "number", -1'000'000'000, 1'000'000'000);
  frame.file = r.string(f, pointer, "file");
  frame.source = r.string(f, pointer, "source");
  frame.particles = uint64_t(r.integer(f, pointer, "particles", 0, int64_t(1) << 40));
  frame.active_voxels = uint64_t(r.integer(f, pointer, "active_voxels", 0, int64_t(1) << 50));
  if (frame.file.empty() || frame.file.find('/') != std::string::npos || frame.file[0] == '.')
    r.fail(pointer + "/file", "a plain file name inside the sequence folder, found \"" + frame.file + "\"");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(folder / frame.file, ec))
    r.fail(pointer + "/file", "an existing particle file, found none at \"" + (folder / frame.file).string() + "\"");
  return frame;
}

void read_frames(const ManifestReader& r, const json& m, const std::filesystem::path& folder,
                 ParticleSequence& s) {
  const json& frames = r.require(m, "", "frames", "an array of frames");
  if (!frames.is_array() || frames.empty()) r.fail("/frames", "a non-empty array of frames, found " + frames.dump());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::string pointer = "/frames/" + std::to_string(i);
    s.frames.push_back(read_frame(r, frames[i], pointer, folder));
    if (i > 0 && s.frames[i].number != s.frames[i - 1].number + 1)
      r.fail(pointer + "/number", "frame number " + std::to_string(s.frames[i - 1].number + 1) +
                                      " (frames ascend one by one), found " + std::to_string(s.frames[i].number));
  }
}

}  // namespace

uint64_t ParticleSequence::max_pair_particles() const {
  uint64_t most = frames.empty() ? 0 : frames.front().particles;
  for (std::size_t i = 1; i < frames.size(); ++i)
    most = std::max(most, frames[i - 1].particles + frames[i].particles);
  // A looping sequence cross-fades its last frame into its first.
  if (frames.size() > 1) most = std::max(most, frames.back().particles + frames.front().particles);
  return most;
}

std::string particle_sequence_frame_name(int64_t number) {
  char name[48];
  std::snprintf(name, sizeof name, "frame_%06lld.pyrop", static_cast<long long>(number));
  return name;
}

std::string particle_sequence_json(const ParticleSequence& s) {
  json frames = json::array();
  for (const ParticleSequenceFrame& f : s.frames)
    frames.push_back({{"number", f.number}, {"file", f.file}, {"source", f.source},
                      {"particles", f.particles}, {"active_voxels", f.active_voxels}});
  json m = {{"format", kParticleSequenceFormat}, {"version", kParticleSequenceVersion}, {"fps", s.fps},
            {"grid", s.grid}, {"extinction", s.extinction}, {"albedo", s.albedo},
            {"error_target", s.error_target}, {"frames", frames}};
  if (s.has_bounds) m["bounds"] = {{"min", s.bounds_min}, {"max", s.bounds_max}};
  return m.dump(1) + "\n";
}

void write_particle_sequence_manifest(const std::filesystem::path& folder, const ParticleSequence& s) {
  write_file_durably((folder / kParticleSequenceManifest).string(), particle_sequence_json(s));
}

ParticleSequence read_particle_sequence(const std::string& folder) {
  const std::filesystem::path dir(folder);
  const ManifestReader r{(dir / kParticleSequenceManifest).string()};
  const json m = read_manifest_json(r.file);
  if (!m.is_object()) r.fail("", "a JSON object, found " + m.dump());
  if (r.string(m, "", "format") != kParticleSequenceFormat)
    r.fail("/format", std::string("\"") + kParticleSequenceFormat + "\", found " + m["format"].dump());
  r.integer(m, "", "version", kParticleSequenceVersion, kParticleSequenceVersion);
  ParticleSequence s;
  s.fps = r.number(m, "", "fps", 0.0, true, 1e6);
  s.grid = r.string(m, "", "grid");
  s.extinction = r.number(m, "", "extinction", 0.0, false, 1e12);
  s.albedo = r.number(m, "", "albedo", 0.0, false, 1.0);
  s.error_target = r.number(m, "", "error_target", 0.0, true, 1.0);
  if (const auto b = m.find("bounds"); b != m.end()) {
    if (!b->is_object()) r.fail("/bounds", "an object {\"min\", \"max\"}, found " + b->dump());
    s.bounds_min = r.vec3(*b, "/bounds", "min");
    s.bounds_max = r.vec3(*b, "/bounds", "max");
    s.has_bounds = true;
  }
  read_frames(r, m, dir, s);
  return s;
}

bool is_particle_sequence(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_directory(path, ec) &&
         std::filesystem::is_regular_file(std::filesystem::path(path) / kParticleSequenceManifest, ec);
}

}  // namespace pyro
