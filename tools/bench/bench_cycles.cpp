#include "tools/bench/bench_cycles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <utility>

#include "components/volume_medium.h"
#include "engine/core/user_error.h"
#include "engine/io/scratch_folder.h"
#include "engine/io/vdb_reader.h"
#include "tools/bench/block_scoring.h"
#include "tools/bench/cycles_render.h"
#include "tools/bench/sun_directions.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/grid_framing.h"
#include "systems/runtime/reference/path_traced_volume.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

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
  CyclesRequest request;
  request.blender = o.blender;
  request.vdb = leaf;
  request.grid = grid.name;
  request.medium = medium;
  request.anisotropy = o.anisotropy;
  request.camera = cam;
  request.width = o.width;
  request.height = o.height;
  request.samples = o.cycles_samples;
  request.bounces = o.bounces;
  const CyclesRender a = render_with_cycles(request, scratch, o.on_note);
  if (a.image.rgb.empty()) return j;
  request.seed = 2;
  const CyclesRender b = render_with_cycles(request, scratch, o.on_note);
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
