// Scene file reader: the generic machinery (strict JSON parsing, typed and range-checked reads,
// unknown-key refusal) lives in engine/io (json_document.h, parameter_dictionary.h); what is here
// is the scene's concepts, each a list of one-line reads plus the few checks that involve
// several fields.
#include "systems/runtime/scene/scene_loader.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "components/light_block.h"
#include "components/stereo_camera.h"
#include "engine/core/file_kind.h"
#include "engine/core/long_json_string.h"
#include "engine/core/sha256.h"
#include "engine/core/user_error.h"
#include "engine/io/json_document.h"
#include "engine/io/parameter_dictionary.h"
#include "engine/mesh/mesh_file_check.h"
#include "systems/runtime/scene/emitter_defaults.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {
namespace {

using json = nlohmann::json;

// ---------------------------------------------------------------------------------------------
// The scene

double length(const glm::vec3& v) {
  const double x = v.x, y = v.y, z = v.z;
  return std::sqrt(x * x + y * y + z * z);
}

constexpr double kMinLength = 1e-6;  // shortest usable direction / camera-to-target distance

void require_nonzero(const glm::vec3& v, const Where& at, std::string_view what) {
  if (length(v) < kMinLength) {
    at.fail("expected a non-zero " + std::string(what) + " (length at least 1e-6), found " +
            format_vec3(v));
  }
}

void read_camera(ObjectReader& r, CameraDescription& c) {
  r.vec3("position", c.position);
  r.vec3("target", c.target);
  r.vec3("up", c.up);
  r.number("fov_y_deg", c.fov_y_deg);
  r.number("near", c.near);
  r.number("far", c.far);
  r.number("orbit_deg_per_second", c.orbit_deg_per_second);
  r.object("stereo", [&](ObjectReader& st) {
    st.number("interocular", c.interocular);
    st.number("zero_parallax_distance", c.zero_parallax_distance);
    EyeOrder order = c.swap_eyes ? EyeOrder::right_left : EyeOrder::left_right;
    st.choice("eye_order", order);
    c.swap_eyes = order == EyeOrder::right_left;
  });

  if (!(c.far > c.near)) {
    r.at("far").fail("expected \"far\" greater than \"near\" (" + format_float(c.near) +
                     "), found " + format_float(c.far));
  }
  const glm::vec3 view = c.target - c.position;
  if (length(view) < kMinLength) {
    r.at("target").fail("expected a target different from the camera position " +
                        format_vec3(c.position) + ", found " + format_vec3(c.target));
  }
  require_nonzero(c.up, r.at("up"), "up vector");
  const double u = length(c.up), d = length(view);
  const double ux = c.up.x / u, uy = c.up.y / u, uz = c.up.z / u;
  const double dx = view.x / d, dy = view.y / d, dz = view.z / d;
  const double sine = std::sqrt((uy * dz - uz * dy) * (uy * dz - uz * dy) +
                                (uz * dx - ux * dz) * (uz * dx - ux * dz) +
                                (ux * dy - uy * dx) * (ux * dy - uy * dx));
  if (sine < 1e-3) {
    r.at("up").fail("expected an up vector not parallel to the view direction " +
                    format_vec3(view) + " (from position to target), found " + format_vec3(c.up));
  }
}

// "light": one directional light and the ambient light, the short form.
void read_light(ObjectReader& r, SceneDescription& s) {
  DirectionalLight sun;
  AmbientLight sky;
  r.vec3("direction", sun.direction);
  r.vec3("color", sun.color);
  r.vec3("ambient", sky.color);
  require_nonzero(sun.direction, r.at("direction"), "light direction");
  s.directional_lights = {sun};
  s.light_keyframes = std::vector<LightKeyframes>(1);
  s.ambient_lights = {sky};
}

// One entry of "lights": {"type": "directional", "direction", "color", "intensity"} or
// {"type": "ambient", "color"}.
void read_light_source(ObjectReader& r, SceneDescription& s) {
  const std::vector<std::string_view>& types = r.key("type", ParameterType::choice).choices;
  r.require("type", "the light type, one of " + quoted_list(types));
  if (read_choice(r, "type", types, 0) == 1) {
    r.vec3("color", s.ambient_lights.emplace_back().color);
    return;
  }
  DirectionalLight& sun = s.directional_lights.emplace_back();
  LightKeyframes& keys = s.light_keyframes.emplace_back();
  r.vec3("direction", sun.direction);
  r.vec3("color", sun.color);
  r.number("intensity", sun.intensity);
  require_nonzero(sun.direction, r.at("direction"), "light direction");
  // "keys": the light over time; the light's own values are each key's defaults.
  r.objects("keys", "an object {\"time\": seconds, \"direction\", \"color\", \"intensity\"}",
            [&](ObjectReader& k, std::size_t) {
              LightKeyframe key{0.0f, sun.direction, sun.color, sun.intensity};
              k.require("time", "the key's time in seconds, >= 0");
              k.number("time", key.time);
              k.vec3("direction", key.direction);
              k.vec3("color", key.color);
              k.number("intensity", key.intensity);
              require_nonzero(key.direction, k.at("direction"), "light direction");
              if (!keys.keys.empty() && !(key.time > keys.keys.back().time))
                k.at("time").fail("expected times in increasing order, found " + format_float(key.time) +
                                  " after " + format_float(keys.keys.back().time));
              keys.keys.push_back(key);
            });
  // Until the light phase animates it (and for what reads the scene's lights once, such as the
  // importer): the first key.
  if (!keys.keys.empty()) sun = {keys.keys.front().direction, keys.keys.front().color, keys.keys.front().intensity};
}

// "scattering": {"anisotropy", "octaves", "attenuation", "contribution", "eccentricity"}.
void read_scattering(ObjectReader& r, SunScattering& s) {
  float g = float(s.anisotropy), a = float(s.octaves.attenuation), b = float(s.octaves.contribution),
        c = float(s.octaves.eccentricity);
  r.number("anisotropy", g);
  r.integer("octaves", s.octaves.octaves);
  r.number("attenuation", a);
  r.number("contribution", b);
  r.number("eccentricity", c);
  s.anisotropy = g;
  s.octaves.attenuation = a;
  s.octaves.contribution = b;
  s.octaves.eccentricity = c;
}

// "shadows": lit media, {"method": "rays" | "map" | "none", "map_size", "map_slices",
// "mesh_map_size", "splat_sunlight": "fragments" | "vertices", "fire_lights", "scattering"}.
void read_shadows(ObjectReader& r, ShadowSettings& s) {
  r.choice("method", s.method);
  r.integer("map_size", s.map_size);
  r.integer("map_slices", s.map_slices);
  r.integer("mesh_map_size", s.mesh_map_size);
  r.choice("splat_sunlight", s.splat_sunlight);
  r.integer("fire_lights", s.fire_lights);
  r.object("scattering", [&](ObjectReader& sc) { read_scattering(sc, s.scattering); });
}

// A particle set's own kind ("particles"), when its entry gives one.
void read_particle_kind(ObjectReader& r, std::optional<ParticleShape>& out) {
  if (r.find("particles") == nullptr) return;
  ParticleShape shape = ParticleShape::gaussian;
  r.choice("particles", shape);
  out = shape;
}

void read_cloud(ObjectReader& r, CloudDescription& c) {
  r.string("name", c.name);
  r.require("count", "the number of particles, an integer in [1, 10000000]");
  r.integer("count", c.count);
  r.number("radius", c.radius);
  r.number("density", c.density);
  r.unit_color("color", c.color);
  r.object("box", [&](ObjectReader& box) {
    box.vec3("min", c.box_min);
    box.vec3("max", c.box_max);
  });
  r.integer("seed", c.seed);
  r.vec3("drift", c.drift);
  r.number("jitter", c.jitter);
  read_particle_kind(r, c.particles);

  static constexpr const char* kAxis[] = {"x", "y", "z"};
  for (glm::length_t i = 0; i < 3; ++i) {
    if (!(c.box_min[i] < c.box_max[i])) {
      r.at("box").fail(std::string("expected \"min\" < \"max\" on every axis, found min.") +
                       kAxis[i] + " = " + format_float(c.box_min[i]) + " >= max." + kAxis[i] +
                       " = " + format_float(c.box_max[i]));
    }
  }
}

bool ends_with_ci(std::string_view s, std::string_view suffix);
std::string resolve_against(const std::string& scene_file, const std::string& relative);

// A mesh file's path: a .gltf, .glb or .obj file, resolved against the scene file's folder. The
// file itself is read with the scene's assets (systems/runtime/scene_runtime/load_scene_assets.h).
void read_mesh_file_path(ObjectReader& r, MeshDescription& m) {
  const std::string expected =
      "expected the path of a mesh file ending in \".gltf\", \".glb\" (glTF 2.0) or \".obj\", relative to "
      "the scene file's folder";
  const json& v = r.require("file", expected);
  if (!v.is_string() || v.get<std::string>().empty()) r.at("file").fail(expected + ", found " + describe(v));
  m.file = v.get<std::string>();
  if (!mesh_file_format(m.file)) r.at("file").fail(expected + ", found " + describe(v));
  m.path = resolve_against(*r.where().file, m.file);
}

void read_mesh(ObjectReader& r, MeshDescription& m) {
  const std::vector<std::string_view>& names = r.key("type", ParameterType::choice).choices;
  const json& type = r.require("type", "the mesh type, one of " + quoted_list(names));
  if (!type.is_string())
    r.at("type").fail("expected a mesh type, one of " + quoted_list(names) + ", found " +
                      describe(type));
  const std::string name = type.get<std::string>();
  const std::optional<MeshKind> kind = enum_from_name<MeshKind>(name);
  if (!kind) {
    std::string message =
        "unknown mesh type " + in_quotes(name) + "; expected one of " + quoted_list(names);
    const std::string hint = suggest(name, names);
    if (hint.rfind("; did you mean", 0) == 0) message += hint;
    r.at("type").fail(message);
  }
  m.kind = *kind;
  m.pointer = r.where().pointer;
  r.refuse_keys_not_for("type", name);
  r.vec3("position", m.position);
  r.vec3("rotation_deg", m.rotation_deg);
  r.number("scale", m.scale);
  r.vec3("color", m.color);
  r.vec3("size", m.size);
  r.number("radius", m.radius);
  r.number("height", m.height);
  if (m.kind == MeshKind::file) read_mesh_file_path(r, m);
}

void read_render(ObjectReader& r, RenderDescription& d) {
  r.choice("billboards", d.billboards);
  r.choice("particles", d.particles);
  r.choice("shading", d.shading);
  r.choice("sort_device", d.sort_device);
  if (d.shading == ParticleShading::explosion && d.particles == ParticleShape::gaussian)
    r.at("shading").fail("\"explosion\" shading needs \"particles\": \"spherical\" or \"planar\"");
  r.number("layer_scale", d.layer_scale);
  if (d.layer_scale != 1.0f && d.layer_scale != 0.5f && d.layer_scale != 0.25f &&
      d.layer_scale != 0.125f) {
    r.at("layer_scale").fail("expected one of 1, 0.5, 0.25, 0.125, found " + format_float(d.layer_scale));
  }
  r.number("motion_blur", d.motion_blur);
  r.object("fire", [&](ObjectReader& f) {
    f.number("t_min", d.fire_t_min);
    f.number("t_max", d.fire_t_max);
    f.number("emission", d.fire_emission);
    f.number("detail_range", d.fire_detail_range);
    if (!(d.fire_t_max > d.fire_t_min))
      f.at("t_max").fail("expected \"t_max\" greater than \"t_min\" (" + format_float(d.fire_t_min) +
                         " K), found " + format_float(d.fire_t_max));
  });
}

// Volume files: a path ending in .vdb or .pyrop (any case).
bool ends_with_ci(std::string_view s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    char c = s[s.size() - suffix.size() + i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != suffix[i]) return false;
  }
  return true;
}

std::string read_volume_path(ObjectReader& r, std::string_view key, const json& v,
                             VolumeFileKind& kind) {
  const std::string expected =
      "expected the path of a volume file ending in \".vdb\" (OpenVDB) or \".pyrop\" (particles), "
      "or of a folder ending in \".pyroseq\" (a particle sequence), relative to the scene file's folder";
  if (!v.is_string() || v.get<std::string>().empty())
    r.at(key).fail(expected + ", found " + describe(v));
  const std::string path = v.get<std::string>();
  if (ends_with_ci(path, ".vdb"))
    kind = VolumeFileKind::vdb;
  else if (ends_with_ci(path, ".pyrop"))
    kind = VolumeFileKind::particles;
  else if (ends_with_ci(path, ".pyroseq") || ends_with_ci(path, ".pyroseq/"))
    kind = VolumeFileKind::sequence;
  else
    r.at(key).fail(expected + ", found " + describe(v));
  return path;
}

// `relative` against the scene file's folder (absolute paths stay as they are).
std::string resolve_against(const std::string& scene_file, const std::string& relative) {
  namespace fs = std::filesystem;
  const fs::path p(relative);
  if (p.is_absolute()) return p.lexically_normal().string();
  return (fs::path(scene_file).parent_path() / p).lexically_normal().string();
}

// A volume file that can be read: a regular file, or for a particle sequence a folder holding
// its manifest (engine/io/particle_sequence.h).
bool is_volume_present(const std::string& path, VolumeFileKind kind) {
  std::error_code ec;
  if (kind == VolumeFileKind::sequence)
    return std::filesystem::is_regular_file(std::filesystem::path(path) / "sequence.json", ec);
  return std::filesystem::is_regular_file(path, ec);
}

// A particle sequence's playback keys, refused on any other volume.
void read_sequence_playback(ObjectReader& r, bool any_sequence, SequencePlayback& p) {
  for (std::string_view key : {"start_frame", "loop", "speed"})
    if (!any_sequence && r.find(key) != nullptr)
      r.at(key).fail("unexpected key " + in_quotes(key) + ": it applies to particle sequences (.pyroseq folders)");
  if (r.find("start_frame") != nullptr) {
    r.integer("start_frame", p.start_frame);
    p.has_start_frame = true;
  }
  r.boolean("loop", p.loop);
  r.number("speed", p.speed);
}

// volumes[].emission.temperature.table: [[value, kelvin], ...], at least two, values ascending.
std::vector<std::array<float, 2>> read_temperature_table(const json& v, const Where& at,
                                                         const Range& kelvin) {
  const std::string expected = "expected an array of 2 to 1024 [value, kelvin] pairs, values strictly ascending";
  if (!v.is_array() || v.size() < 2 || v.size() > 1024) at.fail(expected + ", found " + describe(v));
  std::vector<std::array<float, 2>> table;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Where entry = at.child(std::to_string(i));
    if (!v[i].is_array() || v[i].size() != 2) entry.fail(expected + "; this entry is " + describe(v[i]));
    table.push_back({read_number(v[i][0], entry.child("0"), kAnyRange),
                     read_number(v[i][1], entry.child("1"), kelvin)});
    if (i > 0 && !(table[i][0] > table[i - 1][0]))
      entry.child("0").fail(expected + "; " + format_float(table[i][0]) + " follows " + format_float(table[i - 1][0]));
  }
  return table;
}

// volumes[].emission: {"temperature": {"scale", "offset"} or {"table"}, "intensity"}.
void read_volume_emission(ObjectReader& r, VolumeEmissionDescription& e) {
  r.object("temperature", [&](ObjectReader& t) {
    e.automatic = false;
    if (const json* table = t.find("table")) {
      if (t.find("scale") != nullptr || t.find("offset") != nullptr)
        t.at("table").fail("expected either \"table\" or \"scale\" and \"offset\", found both");
      e.table = read_temperature_table(*table, t.at("table"), t.key("table", ParameterType::custom).range);
      return;
    }
    if (t.find("scale") == nullptr && t.find("offset") == nullptr)
      t.where().fail("expected \"scale\" and \"offset\" (kelvin = scale value + offset) or \"table\", found neither");
    t.number("scale", e.scale);
    t.number("offset", e.offset);
  });
  e.intensity_given = r.find("intensity") != nullptr;
  r.number("intensity", e.intensity);
}

void read_volume(ObjectReader& r, VolumeDescription& v, const std::string& scene_file) {
  v.pointer = r.where().pointer;
  r.string("name", v.name);
  VolumeFileKind file_kind = VolumeFileKind::vdb, fallback_kind = VolumeFileKind::vdb;
  v.file = read_volume_path(
      r, "file",
      r.require("file", "the path of a volume file (.vdb or .pyrop), relative to the scene file's folder"),
      file_kind);
  bool has_fallback = false;
  if (const json* f = r.find("fallback")) {
    v.fallback = read_volume_path(r, "fallback", *f, fallback_kind);
    has_fallback = true;
  }
  const bool any_vdb = file_kind == VolumeFileKind::vdb ||
                       (has_fallback && fallback_kind == VolumeFileKind::vdb);
  // Keys that only mean something for an OpenVDB file.
  const auto vdb_only = [&](std::string_view key) {
    if (!any_vdb && r.find(key) != nullptr) {
      r.at(key).fail("unexpected key " + in_quotes(key) + ": it applies to OpenVDB (.vdb) volumes, "
                     "and " + in_quotes(v.file) + (has_fallback ? " and its fallback are" : " is") +
                     " not: " + (file_kind == VolumeFileKind::sequence ? "a particle sequence (.pyroseq), imported already"
                                                                       : "a particle file (.pyrop)"));
    }
  };
  for (std::string_view key : {"grid", "grid_index", "error", "extinction", "temperature_grid"}) vdb_only(key);
  read_sequence_playback(r, file_kind == VolumeFileKind::sequence || (has_fallback && fallback_kind == VolumeFileKind::sequence),
                         v.sequence);
  r.string("grid", v.grid);
  r.string("temperature_grid", v.temperature_grid);
  r.object("emission", [&](ObjectReader& e) { read_volume_emission(e, v.emission); });
  if (r.find("grid_index") != nullptr) {
    r.integer("grid_index", v.grid_index);
    if (r.find("grid") != nullptr)
      r.at("grid_index").fail("expected either \"grid\" or \"grid_index\", found both");
  }
  r.number("error", v.error);
  r.number("extinction", v.extinction);
  v.anchor_center = read_choice(r, "anchor", r.key("anchor", ParameterType::choice).choices, 0) == 0;
  r.vec3("position", v.position);
  r.number("scale", v.scale);
  if (r.find("size") != nullptr) {
    r.number("size", v.size);
    if (r.find("scale") != nullptr)
      r.at("size").fail("expected either \"scale\" or \"size\", found both");
  }

  // The file, else the fallback: the first that exists.
  const std::string file_path = resolve_against(scene_file, v.file);
  if (is_volume_present(file_path, file_kind)) {
    v.path = file_path;
    v.kind = file_kind;
  } else if (has_fallback) {
    const std::string fallback_path = resolve_against(scene_file, v.fallback);
    if (!is_volume_present(fallback_path, fallback_kind)) {
      r.at("file").fail("expected an existing volume file, found neither one at " + in_quotes(file_path) +
                        " (" + non_regular_file_kind(file_path) + " there) nor at its fallback " +
                        in_quotes(fallback_path) + " (" + non_regular_file_kind(fallback_path) +
                        " there; paths are relative to the scene file's folder)");
    }
    v.path = fallback_path;
    v.kind = fallback_kind;
    v.used_fallback = true;
  } else if (file_kind == VolumeFileKind::sequence) {
    r.at("file").fail("expected a particle sequence folder holding \"sequence.json\" (made by pyro import-vdb), "
                      "found " + (std::filesystem::is_directory(file_path) ? std::string("a folder without it")
                                                                            : non_regular_file_kind(file_path)) +
                      " at " + in_quotes(file_path) + " (paths are relative to the scene file's folder)");
  } else {
    r.at("file").fail("expected an existing volume file, found " + non_regular_file_kind(file_path) +
                      " at " + in_quotes(file_path) + " (paths are relative to the scene file's folder)");
  }
}

// ---------------------------------------------------------------------------------------------
// Flipbook fires (Rose 2007, chapter 4)

// A non-empty array of numbers in `range` (at most `max_size`).
std::vector<float> read_number_array(const json& v, const Where& at, const Range& range,
                                     std::size_t max_size) {
  if (!v.is_array() || v.empty() || v.size() > max_size) {
    at.fail("expected an array of 1 to " + std::to_string(max_size) + " numbers, each in " +
            range.text() + ", found " + describe(v));
  }
  std::vector<float> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(read_number(v[i], at.child(i), range));
  return out;
}

// A non-empty array of integers (either sign) in [-limit, limit].
std::vector<int> read_signed_array(const json& v, const Where& at, int limit, std::size_t max_size) {
  const std::string expected = "expected an array of 1 to " + std::to_string(max_size) +
                               " integers, each in [" + std::to_string(-limit) + ", " +
                               std::to_string(limit) + "], found ";
  if (!v.is_array() || v.empty() || v.size() > max_size) at.fail(expected + describe(v));
  std::vector<int> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const json& e = v[i];
    const double d = e.is_number() ? e.get<double>() : 0.5;
    if (!e.is_number() || d != std::floor(d) || std::fabs(d) > limit)
      at.child(i).fail("expected an integer in [" + std::to_string(-limit) + ", " +
                       std::to_string(limit) + "], found " + describe(e));
    out.push_back(static_cast<int>(d));
  }
  return out;
}

void read_flipbook_group(ObjectReader& r, FlipbookGroup& g) {
  if (const json* v = r.find("offset")) {
    if (!v->is_array() || v->size() != 2)
      r.at("offset").fail("expected [lateral, depth], 2 numbers, found " + describe(*v));
    const Range& range = r.key("offset", ParameterType::custom).range;
    g.offset = glm::vec2(read_number((*v)[0], r.at("offset").child(std::size_t{0}), range),
                         read_number((*v)[1], r.at("offset").child(std::size_t{1}), range));
  }
  r.integer("rows", g.rows);
  r.integer("columns", g.columns);
  r.number("overlap", g.overlap);
  r.number("row_spacing", g.row_spacing);
  const auto limit = [&](std::string_view key) { return static_cast<int>(r.key(key, ParameterType::custom).range.hi); };
  if (const json* v = r.find("column_depths"))
    g.column_depths = read_number_array(*v, r.at("column_depths"), r.key("column_depths", ParameterType::custom).range, 1000);
  if (const json* v = r.find("start_frames"))
    g.start_frames = read_signed_array(*v, r.at("start_frames"), limit("start_frames"), 1000);
  if (const json* v = r.find("row_start_step"))
    g.row_start_step = read_signed_array(json::array({*v}), r.at("row_start_step"), limit("row_start_step"), 1)[0];
  if (const json* v = r.find("increments"))
    g.increments = read_signed_array(*v, r.at("increments"), limit("increments"), 1000);

}

void read_fire(ObjectReader& r, FlipbookFire& f, const std::string& scene_file) {
  r.string("name", f.name);
  r.vec3("position", f.position);
  r.vec3("up", f.up);
  require_nonzero(f.up, r.at("up"), "up vector (the normal of the fire's base)");
  r.number("width", f.width);
  r.number("aspect", f.aspect);
  r.number("intensity", f.intensity);
  r.number("overlap_exponent", f.overlap_exponent);
  r.choice("blend", f.blend);
  r.number("frames_per_second", f.frames_per_second);
  r.number("flicker", f.flicker);
  r.number("flicker_frequency", f.flicker_frequency);
  if (r.find("flipbook") != nullptr) {
    std::string folder;
    r.string("flipbook", folder);
    f.flipbook = resolve_against(scene_file, folder);
    std::error_code ec;
    if (!std::filesystem::is_directory(f.flipbook, ec)) {
      r.at("flipbook").fail("expected a folder of PNG flame frames, found no folder at " +
                            in_quotes(f.flipbook) + " (paths are relative to the scene file's folder)");
    }
  }
  r.object("preparation", [&](ObjectReader& p) {
    if (const json* v = p.find("crop")) {
      const std::vector<float> c = read_number_array(*v, p.at("crop"), p.key("crop", ParameterType::custom).range, 4);
      if (c.size() != 4 || !(c[2] > c[0]) || !(c[3] > c[1]))
        p.at("crop").fail("expected [x0, y0, x1, y1] as fractions of the frame with x0 < x1 and "
                          "y0 < y1, found " + describe(*v));
      f.preparation.crop = glm::vec4(c[0], c[1], c[2], c[3]);
    }
    p.number("base_line", f.preparation.base_line);
    p.number("soften", f.preparation.soften);
    if (f.preparation.base_line + f.preparation.soften > 1.0f)
      p.at("soften").fail("expected base_line + soften at most 1, found " +
                          format_float(f.preparation.base_line + f.preparation.soften));
  });
  if (const json* groups = r.find("groups")) {
    if (!groups->is_array() || groups->size() < r.key("groups", ParameterType::objects).min_items)
      r.at("groups").fail("expected a non-empty array of billboard groups, found " + describe(*groups));
    r.objects("groups", "an object describing a group of billboards",
              [&](ObjectReader& g, std::size_t) { read_flipbook_group(g, f.groups.emplace_back()); });
  } else {
    f.groups.emplace_back();  // the thesis' three overlapped pairs
  }
  std::uint64_t billboards = 0;
  for (const FlipbookGroup& g : f.groups)
    billboards += static_cast<std::uint64_t>(g.rows) * static_cast<std::uint64_t>(g.columns);
  if (billboards > 10'000) {
    r.at("groups").fail("expected at most 10000 billboards in a fire (the sum of rows x columns), "
                        "found " + std::to_string(billboards));
  }
}

// ---------------------------------------------------------------------------------------------
// Explosion emitters

// A number (constant), {"min", "max"} (uniform) or {"mean", "stddev"[, "min", "max"]} (normal,
// clamped to [min, max], by default mean ± 3 stddev).
Distribution read_distribution(const json& v, const Where& at, const Range& range) {
  if (v.is_number()) return Distribution::constant(read_number(v, at, range));
  ObjectReader r(v, at,
                 "a number, {\"min\": a, \"max\": b} (uniform) or {\"mean\": m, \"stddev\": s} (normal)");
  Distribution d;
  const json* mean = r.find("mean");
  const json* stddev = r.find("stddev");
  const json* lo = r.find("min");
  const json* hi = r.find("max");
  r.finish();
  if (mean || stddev) {
    if (!mean || !stddev)
      at.fail("expected both \"mean\" and \"stddev\" for a normal distribution");
    const float m = read_number(*mean, at.child("mean"), range);
    const float sd = read_number(*stddev, at.child("stddev"), kNonNegative);
    const float a = lo ? read_number(*lo, at.child("min"), range) : std::max<float>(m - 3 * sd, range.lo);
    const float b = hi ? read_number(*hi, at.child("max"), range) : std::min<float>(m + 3 * sd, range.hi);
    if (!(a <= m && m <= b))
      at.fail("expected min <= mean <= max, found " + format_float(a) + ", " + format_float(m) + ", " +
              format_float(b));
    return Distribution::normal(m, sd, a, b);
  }
  if (!lo || !hi) at.fail("expected \"min\" and \"max\" (uniform) or \"mean\" and \"stddev\" (normal)");
  const float a = read_number(*lo, at.child("min"), range), b = read_number(*hi, at.child("max"), range);
  if (!(a <= b)) at.fail("expected min <= max, found " + format_float(a) + " > " + format_float(b));
  return Distribution::uniform(a, b);
}

// [[t, value], ...] with t in [0, 1] increasing; value a number or [r, g, b].
LifeCurve read_curve(const json& v, const Where& at, const Range& range, bool color) {
  const std::string what = color ? "[t, [r, g, b]]" : "[t, value]";
  if (!v.is_array() || v.empty())
    at.fail("expected a non-empty array of keys " + what + " with t in [0, 1] increasing, found " + describe(v));
  LifeCurve c;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Where k = at.child(i);
    if (!v[i].is_array() || v[i].size() != 2) k.fail("expected a key " + what + ", found " + describe(v[i]));
    CurveKey key;
    key.t = read_number(v[i][0], k.child(std::size_t{0}), kUnit);
    key.value = color ? read_vec3(v[i][1], k.child(1), range) : glm::vec3(read_number(v[i][1], k.child(1), range));
    if (!c.keys.empty() && !(key.t > c.keys.back().t))
      k.child(std::size_t{0}).fail("expected t greater than the previous key's " + format_float(c.keys.back().t) +
                                   ", found " + format_float(key.t));
    c.keys.push_back(key);
  }
  return c;
}

void read_dynamics(ObjectReader& r, ParticleDynamics& d) {
  r.number("gravity_scale", d.gravity_scale);
  r.number("buoyancy", d.buoyancy);
  r.number("drag", d.drag);
  r.number("turbulence", d.turbulence);
  r.number("turbulence_frequency", d.turbulence_frequency);
  r.number("turbulence_speed", d.turbulence_speed);
  r.integer("turbulence_seed", d.turbulence_seed);
  r.number("cooling", d.cooling);
  r.number("smoke_below", d.smoke_below);
  r.boolean("collide", d.collide);
  r.number("restitution", d.restitution);
  r.number("friction", d.friction);
  r.object("curves", [&](ObjectReader& c) {
    const auto curve = [&](std::string_view key, LifeCurve& out, bool color) {
      if (const json* v = c.find(key)) out = read_curve(*v, c.at(key), c.key(key, ParameterType::custom).range, color);
    };
    curve("size", d.size, false);
    curve("opacity", d.opacity, false);
    curve("temperature", d.temperature, false);
    curve("color", d.color, true);
  });
}

void read_emitter(ObjectReader& r, EmitterDescription& out) {
  Emitter& e = out.emitter;
  r.string("name", e.name);
  r.choice("medium", e.medium);
  apply_medium_defaults(e.medium, e, out.dynamics);  // before the keys that may override them
  r.object("shape", [&](ObjectReader& s) {
    s.choice("type", e.shape);
    s.vec3("position", e.position);
    s.number("radius", e.radius);
    s.boolean("surface", e.surface);
    s.vec3("half_extent", e.half_extent);
    s.vec3("axis", e.axis);
    require_nonzero(e.axis, s.at("axis"), "disc axis");
  });
  r.object("pattern", [&](ObjectReader& p) {
    p.number("frequency", e.pattern.frequency);
    p.number("speed", e.pattern.speed);
    p.number("threshold", e.pattern.threshold);
  });
  r.number("rate", e.rate);
  r.number("start", e.start);
  r.number("duration", e.duration);
  r.objects("bursts", "an object {\"time\": seconds, \"count\": n}", [&](ObjectReader& b, std::size_t) {
    EmitterBurst burst;
    b.number("time", burst.time);
    b.require("count", "the number of particles, an integer in [0, 10000000]");
    b.integer("count", burst.count);
    e.bursts.push_back(burst);
  });
  std::stable_sort(e.bursts.begin(), e.bursts.end(),
                   [](const EmitterBurst& a, const EmitterBurst& b) { return a.time < b.time; });
  r.vec3("direction", e.direction);
  require_nonzero(e.direction, r.at("direction"), "direction");
  r.number("cone_deg", e.cone_deg);
  r.boolean("radial", e.radial);
  const std::pair<std::string_view, Distribution*> dists[] = {{"speed", &e.speed},
                                                              {"size", &e.size},
                                                              {"lifetime", &e.lifetime},
                                                              {"density", &e.density},
                                                              {"temperature", &e.temperature}};
  for (const auto& [key, target] : dists)
    if (const json* v = r.find(key))
      *target = read_distribution(*v, r.at(key), r.key(key, ParameterType::custom).range);
  r.vec3("color", e.color);
  r.integer("budget", e.budget);
  r.integer("seed", e.seed);
  r.object("dynamics", [&](ObjectReader& d) { read_dynamics(d, out.dynamics); });
  read_particle_kind(r, out.particles);
}

void read_environment(ObjectReader& r, SimulationEnvironment& env, float& prewarm) {
  r.vec3("gravity", env.gravity);
  r.vec3("wind", env.wind);
  r.number("ambient_temperature", env.ambient_temperature);
  r.object("ground", [&](ObjectReader& g) {
    env.ground = true;
    g.number("height", env.ground_height);
  });
  r.objects("spheres", "an object {\"center\": [x, y, z], \"radius\": r}", [&](ObjectReader& s, std::size_t) {
    SphereCollider c;
    s.vec3("center", c.center);
    s.number("radius", c.radius);
    env.spheres.push_back(c);
  });
  r.objects("boxes", "an object {\"min\": [x, y, z], \"max\": [x, y, z]}", [&](ObjectReader& b, std::size_t) {
    BoxCollider c;
    b.vec3("min", c.min);
    b.vec3("max", c.max);
    for (glm::length_t i = 0; i < 3; ++i)
      if (!(c.min[i] < c.max[i])) b.at("max").fail("expected \"min\" < \"max\" on every axis");
    env.boxes.push_back(c);
  });
  r.integer("particle_budget", env.particle_budget);
  r.number("prewarm", prewarm);
}

SceneDescription read_scene(ObjectReader& r) {
  SceneDescription s;
  r.string("name", s.name);
  r.integer("seed", s.seed);
  r.object("output", [&](ObjectReader& o) {
    o.integer("width", s.width);
    o.integer("height", s.height);
    o.number("fps", s.frames_per_second);
    o.choice("background", s.output_background);
  });
  r.vec3("background", s.background);
  r.object("camera", [&](ObjectReader& c) { read_camera(c, s.camera); });
  r.object("light", [&](ObjectReader& l) { read_light(l, s); });
  r.object("footprint", [&](ObjectReader& f) {
    f.integer("size", s.footprint.size);
    f.integer("intervals", s.footprint.intervals);
  });
  r.object("render", [&](ObjectReader& d) { read_render(d, s.render); });
  r.objects("clouds", "an object describing a cloud",
            [&](ObjectReader& c, std::size_t) { read_cloud(c, s.clouds.emplace_back()); });
  r.objects("meshes", "an object describing a mesh",
            [&](ObjectReader& m, std::size_t) { read_mesh(m, s.meshes.emplace_back()); });
  r.objects("volumes", "an object describing a volume", [&](ObjectReader& v, std::size_t) {
    read_volume(v, s.volumes.emplace_back(), *r.where().file);
  });
  r.object("environment", [&](ObjectReader& e) { read_environment(e, s.environment, s.prewarm); });
  r.objects("emitters", "an object describing an emitter",
            [&](ObjectReader& e, std::size_t) { read_emitter(e, s.emitters.emplace_back()); });
  r.objects("fires", "an object describing a flipbook fire", [&](ObjectReader& f, std::size_t) {
    read_fire(f, s.fires.emplace_back(), *r.where().file);
  });
  r.object("budget", [&](ObjectReader& b) {
    b.integer("particles", s.budget.particles);
    std::uint64_t memory_mib = s.budget.memory_bytes >> 20;
    b.integer("memory_mib", memory_mib);
    s.budget.memory_bytes = memory_mib << 20;
    b.integer("texture_size", s.budget.texture_size);
  });
  r.object("quality", [&](ObjectReader& q) {
    q.require("max_rmse", "a number in (0, 1], the largest image RMSE accepted");
    q.number("max_rmse", s.quality.max_rmse);
  });
  r.object("shadows", [&](ObjectReader& sh) { read_shadows(sh, s.shadows.emplace()); });
  if (r.find("lights") != nullptr) {
    if (r.find("light") != nullptr)
      r.at("lights").fail("expected either \"light\" or \"lights\", found both");
    s.directional_lights.clear();
    s.light_keyframes.clear();
    s.ambient_lights.clear();
    r.objects("lights", "an object describing a light",
              [&](ObjectReader& l, std::size_t) { read_light_source(l, s); });
    if (s.directional_lights.size() > size_t(kMaxSuns))
      r.at("lights").fail("expected at most " + std::to_string(kMaxSuns) + " directional lights, found " +
                          std::to_string(s.directional_lights.size()));
  }
  std::string schema;  // "$schema": the file's JSON Schema, for editors; nothing for the engine
  r.string("$schema", schema);
  r.finish();
  return s;
}

}  // namespace

SceneDescription parse_scene(const std::string& text, const std::string& file_name_for_messages) {
  const std::string& file = file_name_for_messages;
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw UserError(file, "", "expected a JSON object describing the scene, found an empty file");
  }
  // No scene string (names, paths) is near this long; refused before the parser copies it.
  constexpr std::size_t kMaxStringBytes = 1 << 16;
  if (const auto long_string = find_long_json_string(text, kMaxStringBytes))
    throw UserError(file, line_and_column(text, long_string->offset + 1),
                    "strings of at most " + std::to_string(kMaxStringBytes) +
                        " bytes, found one of " + std::to_string(long_string->bytes) + " bytes");
  const JsonDocument document = parse_json_document(text);
  if (document.failed) throw UserError(file, document.error_place, document.error_message);

  const json& root = document.root;
  if (!root.is_object()) {
    throw UserError(
        file, "", "expected a JSON object at the top level of the scene, found " + describe(root));
  }
  ObjectReader reader(root, Where{&file, ""}, scene_keys());
  SceneDescription scene = read_scene(reader);
  scene.file = file;
  // The scene as parsed, not its bytes: key order, spacing and number spelling do not count, nor
  // does "$schema", which only editors read.
  json canonical = root;
  canonical.erase("$schema");
  scene.content_digest = sha256_hex(canonical.dump());
  return scene;
}

namespace {

// Everything `fd` holds until its end. Throws UserError naming `path` on a read error.
std::string read_all(int fd, const std::string& path) {
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw UserError(path, "", std::string("cannot read scene file: ") + std::strerror(errno));
    if (n == 0) return text;
    text.append(buffer, static_cast<std::size_t>(n));
  }
}

// A file descriptor closed when it goes out of scope.
struct OpenFile {
  int fd = -1;
  ~OpenFile() {
    if (fd >= 0) ::close(fd);
  }
};

// A pipe (bash's <(...), standard input) is read once; a named FIFO that no program writes to
// would block the open and every read forever, so it is opened without blocking and refused when
// nothing arrives within a second.
std::string read_fifo(const std::string& path) {
  const OpenFile file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) throw UserError(path, "", std::string("cannot open scene file: ") + std::strerror(errno));
  struct pollfd p {file.fd, POLLIN, 0};
  int ready;
  do ready = ::poll(&p, 1, 1000);
  while (ready < 0 && errno == EINTR);
  if (ready == 0)
    throw UserError(path, "", "expected a scene file, found a FIFO (named pipe) that no program "
                              "wrote to within 1 s");
  ::fcntl(file.fd, F_SETFL, ::fcntl(file.fd, F_GETFL) & ~O_NONBLOCK);
  return read_all(file.fd, path);
}

}  // namespace

std::string read_scene_text(const std::string& path) {
  if (path == "-") return read_all(STDIN_FILENO, "<standard input>");
  if (is_fifo(path)) return read_fifo(path);
  const std::string kind = non_regular_file_kind(path);
  if (kind == "no file") throw UserError(path, "", std::string("cannot open scene file: ") + std::strerror(ENOENT));
  if (!kind.empty()) throw UserError(path, "", "expected a scene file, found " + kind);
  const OpenFile file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) throw UserError(path, "", std::string("cannot open scene file: ") + std::strerror(errno));
  return read_all(file.fd, path);
}

SceneDescription load_scene(const std::string& path) {
  return parse_scene(read_scene_text(path), path == "-" ? "<standard input>" : path);
}

}  // namespace pyro
