#include "tools/bench/bench_cycles_fire.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <vector>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/scratch_folder.h"
#include "engine/io/vdb_reader.h"
#include "engine/io/vdb_temperature_grid.h"
#include "engine/math/blackbody.h"
#include "engine/math/temperature_emission.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/grid_framing.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "tools/bench/cycles_render.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

// Rec. 709 luminance of linear RGB: the weights of Cycles' RGB to BW node in Blender's default
// (Rec. 709) scene-linear space, and of the engine's linear sRGB (the same primaries).
double luminance_of(const glm::dvec3& rgb) { return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z; }

glm::dvec3 pixel(const RgbImage& image, int x, int y) {
  const float* c = image.at(x, y);
  return {c[0], c[1], c[2]};
}

// The temperature in kelvin of every voxel, for Cycles. Where there is no density nothing emits,
// but Cycles interpolates the temperature trilinearly, so a flame's edge would blend towards the
// empty voxels' temperature (0 K, or 1000 K for a normalised heat of 0) and redden; an empty voxel
// takes instead the mean temperature of its non-empty neighbours (the 26 around it: all that an
// interpolation at the flame's edge reaches), and 0 without any. The grids hold one empty voxel
// around the active box for that (padded).
std::vector<float> kelvin_for_cycles(const DenseGrid& density, const DenseGrid& heat, const TemperatureMapping& mapping) {
  std::vector<float> kelvin(density.size(), 0.0f);
  const auto index = [&](int x, int y, int z) { return (size_t(z) * density.dims[1] + y) * density.dims[0] + x; };
  for (int z = 0; z < density.dims[2]; ++z)
    for (int y = 0; y < density.dims[1]; ++y)
      for (int x = 0; x < density.dims[0]; ++x) {
        if (density.values[index(x, y, z)] > 0.0f) {
          kelvin[index(x, y, z)] = float(mapping.kelvin(heat.values[index(x, y, z)]));
          continue;
        }
        double sum = 0.0;
        int count = 0;
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int u = x + dx, v = y + dy, w = z + dz;
              if (u < 0 || v < 0 || w < 0 || u >= density.dims[0] || v >= density.dims[1] || w >= density.dims[2] ||
                  !(density.values[index(u, v, w)] > 0.0f))
                continue;
              sum += mapping.kelvin(heat.values[index(u, v, w)]);
              ++count;
            }
        kelvin[index(x, y, z)] = count > 0 ? float(sum / count) : 0.0f;
      }
  return kelvin;
}

// The grid with one voxel more on every side, holding 0 (so that the temperature can be carried
// past the active box's faces, where Cycles interpolates towards the background).
DenseGrid padded(const DenseGrid& grid) {
  DenseGrid out = grid;
  for (int a = 0; a < 3; ++a) {
    out.origin[a] -= 1;
    out.dims[a] += 2;
  }
  out.values.assign(out.box_voxels(), 0.0f);
  for (int z = 0; z < grid.dims[2]; ++z)
    for (int y = 0; y < grid.dims[1]; ++y)
      for (int x = 0; x < grid.dims[0]; ++x)
        out.values[(size_t(z + 1) * out.dims[1] + (y + 1)) * out.dims[0] + (x + 1)] = grid.at(x, y, z);
  return out;
}

// The density, the temperature in kelvin (kelvin_for_cycles) and the emission's luminance per
// world unit at intensity 1 (0 where it does not glow), in one file in leaf voxels over the
// density's box and one voxel around it, for Cycles.
void write_fire_grids(const DenseGrid& active_density, const DenseGrid& active_heat, const TemperatureEmission& unit,
                      double extinction, const std::string& path) {
  const DenseGrid density = padded(active_density), heat = padded(active_heat);
  const std::array<double, 3> voxel = axis_voxel_sizes(density);
  const glm::dmat4& m = density.index_to_world;
  VdbGridToWrite grids[3];
  const char* names[3] = {"density", "kelvin", "glow"};
  for (int g = 0; g < 3; ++g) {
    grids[g].name = names[g];
    grids[g].origin = density.origin;
    grids[g].dims = density.dims;
    grids[g].voxel_size = voxel;
    grids[g].translation = {m[3][0], m[3][1], m[3][2]};
    grids[g].values.resize(density.size());
  }
  grids[1].values = kelvin_for_cycles(density, heat, unit.mapping);
  for (size_t i = 0; i < density.size(); ++i) {
    const double rho = std::max(0.0f, density.values[i]);
    grids[0].values[i] = float(rho);
    grids[2].values[i] = float(extinction * rho * luminance_of(glm::dvec3(emitted_radiance(unit, heat.values[i]))));
  }
  write_vdb_grids(path, {grids[0], grids[1], grids[2]});
}

// The first frame of the scene file `path` at width x height, opened as every command opens one.
RgbImage draw_scene_file(const std::string& path, int width, int height) {
  OpenSceneOptions options;
  options.runtime.readback = true;
  options.runtime.width_override = width;
  options.runtime.height_override = height;
  const OpenedScene opened = open_scene(path, options);
  opened.runtime->draw_frame(0);
  return rgb_of(opened.runtime->image());
}

nlohmann::json vec3_json(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// The vdb template's volume entry for `file` (its keys, the file replaced).
nlohmann::json template_scene(const std::string& file) {
  std::ifstream in(content_path("templates/vdb.json"));
  nlohmann::json scene = nlohmann::json::parse(in);
  scene.erase("$schema");
  scene["volumes"][0]["file"] = fs::absolute(file).string();
  return scene;
}

// The template's volume at its own coordinates, seen from `cam`, lit by nothing but its fire.
std::string write_fire_only_scene(const std::string& file, const CameraDescription& cam, double error,
                                  const fs::path& scratch) {
  nlohmann::json scene = template_scene(file);
  scene["background"] = {0, 0, 0};
  scene["light"]["color"] = {0, 0, 0};
  scene["light"]["ambient"] = {0, 0, 0};
  scene["camera"] = {{"position", vec3_json(cam.position)}, {"target", vec3_json(cam.target)},
                     {"up", vec3_json(cam.up)},             {"fov_y_deg", cam.fov_y_deg},
                     {"near", cam.near},                    {"far", cam.far}};
  nlohmann::json& v = scene["volumes"][0];
  v.erase("size");
  v.erase("position");
  v["anchor"] = "origin";
  v["error"] = error;
  const std::string path = (scratch / "fire_only.json").string();
  std::ofstream(path) << scene.dump(1);
  return path;
}

// Pixels of the template's own frame (its size, its daylight) with a channel past white.
nlohmann::json template_clipping(const std::string& file, const fs::path& scratch) {
  const nlohmann::json scene = template_scene(file);
  const std::string path = (scratch / "template.json").string();
  std::ofstream(path) << scene.dump(1);
  const int w = scene["output"]["width"].get<int>(), h = scene["output"]["height"].get<int>();
  const RgbImage image = draw_scene_file(path, w, h);
  int clipped = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3)
    if (std::max({image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]}) > 1.0f) ++clipped;
  return {{"template_clipped_pixels", clipped}, {"template_pixels", w * h}};
}

nlohmann::json bench_one_fire(const CyclesFireBenchOptions& o, const std::string& file, const fs::path& scratch) {
  std::string note;
  const DenseGrid density = read_vdb_grid(file, {"", -1}, &note);
  if (!note.empty() && o.on_note) o.on_note(file + ": " + note);
  const std::optional<VdbGridInfo> info = choose_temperature_grid(file, list_vdb_grids(file), "", "FILE");
  if (!info) throw UserError(file, "FILE", "a VDB file with a temperature grid (\"temperature\", \"heat\" or \"flame\")");
  const DenseGrid heat = read_temperature_grid(file, *info, density);
  const TemperatureEmission unit =
      make_temperature_emission(automatic_temperature_mapping(heat.max_value), 1.0, heat.max_value);
  const double extinction = default_extinction(density);
  const CameraDescription cam = framing_camera(density);
  nlohmann::json j = {{"file", file}, {"temperature_grid", info->name}, {"hottest_kelvin", unit.hottest_kelvin},
                      {"extinction", extinction}};
  j.update(template_clipping(file, scratch));
  const RgbImage ours = draw_scene_file(write_fire_only_scene(file, cam, o.error, scratch), o.width, o.height);
  const std::string grids = (scratch / "fire_grids.vdb").string();
  write_fire_grids(density, heat, unit, extinction, grids);
  CyclesRequest request;
  request.blender = o.blender;
  request.vdb = grids;
  request.grid = "density";
  request.temperature_grid = "kelvin";
  request.emission_grid = "glow";
  request.medium.extinction = extinction;
  request.medium.albedo = 0.0;
  request.medium.light_color = glm::dvec3(0.0);
  request.medium.ambient = glm::dvec3(0.0);
  request.medium.background = glm::dvec3(0.0);
  request.camera = cam;
  request.width = o.width;
  request.height = o.height;
  request.samples = o.cycles_samples;
  const CyclesRender cycles = render_with_cycles(request, scratch, o.on_note);
  j["cycles_seconds"] = cycles.image.rgb.empty() ? nlohmann::json(nullptr) : nlohmann::json(cycles.seconds);
  if (!cycles.image.rgb.empty()) j.update(score_fire_against_cycles(ours, cycles.image, o.emitting_fraction));
  return j;
}

}  // namespace

nlohmann::json bench_cycles_fire(const CyclesFireBenchOptions& o) {
  if (!program_exists(o.blender))
    throw UserError(o.blender, "--blender",
                    "the blender program, on PATH or as a path (Debian: apt-get install --no-install-recommends blender)");
  ProgressTask progress(o.progress, "bench cycles-fire", o.files.size());
  const ScratchFolder scratch("pyro-bench-cycles-fire");
  nlohmann::json files = nlohmann::json::array();
  for (size_t i = 0; i < o.files.size(); ++i) {
    progress.stage(i, fs::path(o.files[i]).filename().string());
    files.push_back(bench_one_fire(o, o.files[i], scratch.path));
  }
  progress.finish();
  return {{"blender", o.blender},
          {"width", o.width},
          {"height", o.height},
          {"cycles_samples", o.cycles_samples},
          {"error", o.error},
          {"emitting_fraction", o.emitting_fraction},
          {"files", files}};
}

nlohmann::json score_fire_against_cycles(const RgbImage& ours, const RgbImage& cycles, double fraction) {
  double brightest = 0.0;
  for (int y = 0; y < cycles.height; ++y)
    for (int x = 0; x < cycles.width; ++x) brightest = std::max(brightest, luminance_of(pixel(cycles, x, y)));
  glm::dvec3 sum_ours(0.0), sum_cycles(0.0);
  std::vector<glm::ivec2> emitting;
  for (int y = 0; y < cycles.height; ++y)
    for (int x = 0; x < cycles.width; ++x)
      if (brightest > 0.0 && luminance_of(pixel(cycles, x, y)) >= fraction * brightest) {
        emitting.emplace_back(x, y);
        sum_ours += pixel(ours, x, y);
        sum_cycles += pixel(cycles, x, y);
      }
  if (emitting.empty() || luminance_of(sum_ours) <= 0.0) return {{"emitting_pixels", emitting.size()}};
  const double mean_ours = luminance_of(sum_ours) / double(emitting.size());
  const double mean_cycles = luminance_of(sum_cycles) / double(emitting.size());
  std::vector<double> differences;
  double luminance_error = 0.0;
  for (const glm::ivec2& p : emitting) {
    const glm::dvec3 a = pixel(ours, p.x, p.y), b = pixel(cycles, p.x, p.y);
    if (luminance_of(a) > 0.0) differences.push_back(glm::length(linear_srgb_chromaticity(a) - linear_srgb_chromaticity(b)));
    const double d = luminance_of(a) / mean_ours - luminance_of(b) / mean_cycles;
    luminance_error += d * d;
  }
  std::sort(differences.begin(), differences.end());
  const auto quantile = [&](double q) {
    return differences.empty() ? 0.0 : differences[std::min(differences.size() - 1, size_t(q * differences.size()))];
  };
  const glm::dvec2 xy_ours = linear_srgb_chromaticity(sum_ours), xy_cycles = linear_srgb_chromaticity(sum_cycles);
  return {{"emitting_pixels", emitting.size()},
          {"chromaticity_ours", {xy_ours.x, xy_ours.y}},
          {"chromaticity_cycles", {xy_cycles.x, xy_cycles.y}},
          {"chromaticity_difference", glm::length(xy_ours - xy_cycles)},
          {"pixel_chromaticity_difference_median", quantile(0.5)},
          {"pixel_chromaticity_difference_p90", quantile(0.9)},
          {"relative_luminance_rmse", std::sqrt(luminance_error / double(emitting.size()))}};
}

}  // namespace pyro
