#include "tools/bench/bench_cycles.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>

#include "components/volume_medium.h"
#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/scratch_folder.h"
#include "engine/io/vdb_reader.h"
#include "tools/bench/block_scoring.h"
#include "tools/bench/sun_directions.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/grid_framing.h"
#include "systems/runtime/reference/path_traced_volume.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

// A folder of its own under the system's temporary folder, removed with everything in it.
// Whether `program` runs: a path to an executable file, or a name found on PATH.
bool program_exists(const std::string& program) {
  if (program.find('/') != std::string::npos) return access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
  return false;
}

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string spaced_vector(const glm::dvec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g", v.x, v.y, v.z);
  return buf;
}

// The grid again, its tiles spread into leaf voxels, with the same voxel size and translation.
void write_leaf_copy(const DenseGrid& grid, const std::string& path) {
  const glm::dmat4& m = grid.index_to_world;
  const double v = m[0][0];
  bool uniform = v > 0.0 && m[1][1] == v && m[2][2] == v;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) uniform = uniform && (c == r || m[c][r] == 0.0);
  if (!uniform)
    throw UserError(grid.file, "grid \"" + grid.name + "\"",
                    "a uniform voxel size without rotation (the Cycles comparison writes the grid again so)");
  write_vdb_fog_volume(path, grid.name, grid.origin, grid.dims, grid.values, v, {m[3][0], m[3][1], m[3][2]});
}

struct CyclesRender {
  RgbImage image;  // empty when the run failed
  double seconds = 0.0;
};

// A colour PFM (rows bottom first, little-endian when the scale is negative) as an RgbImage.
RgbImage read_pfm(const fs::path& path, int width, int height) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int w = 0, h = 0;
  double scale = 0.0;
  if (!(in >> magic >> w >> h >> scale) || magic != "PF" || w != width || h != height || scale >= 0.0) return {};
  in.get();
  std::vector<float> rows(size_t(3) * w * h);
  if (!in.read(reinterpret_cast<char*>(rows.data()), std::streamsize(rows.size() * sizeof(float)))) return {};
  RgbImage img;
  img.width = w;
  img.height = h;
  img.rgb.resize(rows.size());
  for (int y = 0; y < h; ++y)
    std::copy_n(&rows[size_t(3) * w * (h - 1 - y)], 3 * w, img.at(0, y));
  return img;
}

CyclesRender render_with_cycles(const CyclesBenchOptions& o, const std::string& leaf, const DenseGrid& grid,
                                const VolumeMedium& medium, const CameraDescription& cam, int seed,
                                const fs::path& scratch) {
  const fs::path out = scratch / ("cycles_" + std::to_string(seed) + ".pfm"), log = scratch / "cycles.log";
  const std::pair<const char*, std::string> args[] = {
      {"--vdb", quoted(leaf)},
      {"--grid", quoted(grid.name)},
      {"--extinction", num(medium.extinction)},
      {"--albedo", num(medium.albedo)},
      {"--anisotropy", num(o.anisotropy)},
      {"--sun-direction", spaced_vector(medium.light_direction)},
      {"--light-color", spaced_vector(medium.light_color)},
      {"--background", spaced_vector(medium.background)},
      {"--camera-position", spaced_vector(glm::dvec3(cam.position))},
      {"--camera-target", spaced_vector(glm::dvec3(cam.target))},
      {"--camera-up", spaced_vector(glm::dvec3(cam.up))},
      {"--fov-y", num(cam.fov_y_deg)},
      {"--width", std::to_string(o.width)},
      {"--height", std::to_string(o.height)},
      {"--samples", std::to_string(o.cycles_samples)},
      {"--bounces", std::to_string(o.bounces)},
      {"--seed", std::to_string(seed)},
      {"--out", quoted(out.string())}};
  std::string cmd =
      quoted(o.blender) + " -b --factory-startup --python " + quoted(content_path("cycles/render_volume.py")) + " --";
  for (const auto& [flag, value] : args) cmd += std::string(" ") + flag + " " + value;
  cmd += " > " + quoted(log.string()) + " 2>&1";
  const auto t = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  CyclesRender r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  if (status == 0) r.image = read_pfm(out, o.width, o.height);
  if (r.image.rgb.empty() && o.on_note) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    o.on_note("Cycles failed (status " + std::to_string(status) + "): " + cmd + "\n" + text.str().substr(0, 2000));
  }
  return r;
}

// The image plus `offset` in each channel of every pixel that shows the medium.
RgbImage offset_where_medium_shows(const RgbImage& image, const std::array<double, 3>& background, double offset) {
  RgbImage out = image;
  if (offset == 0.0) return out;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (pixel_shows_medium(image, x, y, background))
        for (int c = 0; c < 3; ++c) out.at(x, y)[c] = float(image.at(x, y)[c] + offset);
  return out;
}

nlohmann::json score_cycles_direction(const CyclesBenchOptions& o, const DenseGrid& grid, const std::string& leaf,
                               const VolumeMedium& medium, const fs::path& scratch) {
  const CameraDescription cam = framing_camera(grid);
  PathTraceOptions trace;
  trace.samples_per_pixel = o.samples;
  trace.anisotropy = o.anisotropy;
  trace.threads = o.threads;
  const PathTracedImage traced = path_trace_volume(grid, camera_frame(cam, o.width, o.height), medium, trace);
  const std::array<double, 3> background{medium.background.x, medium.background.y, medium.background.z};
  const RgbImage ours = offset_where_medium_shows(traced.image, background, o.offset_ours);
  const glm::dvec3 d = medium.light_direction;
  nlohmann::json j = {{"direction", {d.x, d.y, d.z}},
                      {"path_traced_seconds", traced.seconds},
                      {"monte_carlo_error", traced.monte_carlo_error},
                      {"cycles_seconds", nullptr},
                      {"cycles_noise", nullptr},
                      {"noise_rmse", nullptr},
                      {"rmse_vs_cycles", nullptr},
                      {"block_rmse_vs_cycles", nullptr},
                      {"block_noise_rmse", nullptr},
                      {"bias_rmse", nullptr},
                      {"mean_difference", nullptr},
                      {"mean_difference_error", nullptr}};
  const CyclesRender a = render_with_cycles(o, leaf, grid, medium, cam, 1, scratch);
  if (a.image.rgb.empty()) return j;
  const CyclesRender b = render_with_cycles(o, leaf, grid, medium, cam, 2, scratch);
  j["cycles_seconds"] = a.seconds;
  j["rmse_vs_cycles"] = image_rmse(ours, a.image);
  const std::vector<bool> medium_blocks = blocks_showing_medium(traced.image, o.block, background);
  j["block_rmse_vs_cycles"] = block_rmse(ours, a.image, o.block, medium_blocks);
  if (b.image.rgb.empty()) return j;
  const double cycles_noise = image_rmse(a.image, b.image) / std::sqrt(2.0);
  j["cycles_noise"] = cycles_noise;
  j["noise_rmse"] = std::hypot(traced.monte_carlo_error, cycles_noise);
  const BlockScore blocks =
      block_score(ours, a.image, o.block, medium_blocks,
                  independent_block_noise(traced.monte_carlo_error, traced.image, o.block, medium_blocks),
                  block_rmse(a.image, b.image, o.block, medium_blocks) / std::sqrt(2.0));
  j["block_noise_rmse"] = blocks.noise_rmse;
  j["bias_rmse"] = blocks.bias_rmse;
  const MeanDifference mean = medium_mean_difference(ours, a.image, traced.image, background);
  j["mean_difference"] = mean.mean;
  j["mean_difference_error"] = mean.standard_error;
  return j;
}

}  // namespace

nlohmann::json bench_cycles(const CyclesBenchOptions& o) {
  if (!program_exists(o.blender))
    throw UserError(o.blender, "--blender",
                    "the blender program, on PATH or as a path (Debian: apt-get install --no-install-recommends blender)");
  ProgressTask progress(o.progress, "bench cycles", o.files.size() * size_t(o.directions));
  const ScratchFolder scratch("pyro-bench-cycles");
  nlohmann::json files = nlohmann::json::array();
  size_t done = 0;
  for (const std::string& file : o.files) {
    std::string note;
    const DenseGrid grid = read_vdb_grid(file, {o.grid, -1}, &note);
    if (!note.empty() && o.on_note) o.on_note(file + ": " + note);
    if (grid.empty()) throw UserError(file, "grid \"" + grid.name + "\"", "a grid with active voxels to light");
    const std::string leaf = (scratch.path / ("leaf_" + std::to_string(files.size()) + ".vdb")).string();
    write_leaf_copy(grid, leaf);
    VolumeMedium medium;
    medium.extinction = default_extinction(grid);
    medium.albedo = o.albedo;
    medium.ambient = glm::dvec3(0.0);
    nlohmann::json directions = nlohmann::json::array();
    std::optional<double> worst, worst_bias;
    for (int k = 0; k < o.directions; ++k) {
      progress.stage(done++, fs::path(file).filename().string() + ", direction " + std::to_string(k + 1));
      medium.light_direction = sun_direction(k, o.directions);
      directions.push_back(score_cycles_direction(o, grid, leaf, medium, scratch.path));
      if (!directions.back()["rmse_vs_cycles"].is_null())
        worst = std::max(worst.value_or(0.0), directions.back()["rmse_vs_cycles"].get<double>());
      if (!directions.back()["bias_rmse"].is_null())
        worst_bias = std::max(worst_bias.value_or(0.0), directions.back()["bias_rmse"].get<double>());
    }
    files.push_back({{"file", file}, {"grid", grid.name}, {"extinction", medium.extinction},
                     {"directions", directions},
                     {"max_rmse_vs_cycles", worst ? nlohmann::json(*worst) : nlohmann::json(nullptr)},
                     {"max_bias_rmse", worst_bias ? nlohmann::json(*worst_bias) : nlohmann::json(nullptr)}});
  }
  progress.finish();
  return {{"blender", o.blender},   {"width", o.width},           {"height", o.height},
          {"samples", o.samples},   {"cycles_samples", o.cycles_samples}, {"bounces", o.bounces},
          {"albedo", o.albedo},     {"anisotropy", o.anisotropy}, {"block", o.block},
          {"offset_ours", o.offset_ours}, {"files", files}};
}

}  // namespace pyro
