// pyro bench vdb FILE [--grid NAME] [--error E] [--width W] [--height H] [--json]
// One view of one grid, rendered three ways in one run: the splatting pipeline (the imported
// particles through the real GL passes; best of 3 frames), the CPU reference (systems/reference),
// and OpenVDB's vdb_render (Debian's libopenvdb-tools) as a separate process with the same camera
// (position, look-at, up, horizontal field of view), resolution, light direction and colour, and
// absorption / scattering per voxel (vdb_render integrates in voxel units: sigma per voxel =
// extinction * voxel length, split by the albedo; its shadow "gain" is set to 0). vdb_render has
// no ambient term, so its image is not expected to match ours; it is timed, not scored.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "systems/cloud_import/cloud_import.h"
#include "systems/reference/volume_reference.h"
#include "systems/scene_runtime/particle_snapshot.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "systems/cloud_import/grid_framing.h"

namespace pyro::cli {

namespace {

struct BenchVdbArgs {
  std::string file, grid, vdb_render = "vdb_render";
  int grid_index = -1;
  double error = 0.03;
  int width = 512, height = 512;
  bool json = false;
};

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string vec(const glm::dvec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.9g", v.x, v.y, v.z);
  return buf;
}

void run_bench_vdb(const BenchVdbArgs& a) {
  Progress progress("bench vdb", 5);
  progress.stage(0, "read");
  std::string note;
  const DenseGrid grid = read_vdb_grid(a.file, {a.grid, a.grid_index}, &note);
  if (!note.empty()) std::fprintf(stderr, "pyro bench vdb: %s: %s\n", a.file.c_str(), note.c_str());
  if (grid.empty()) throw UserError(a.file, "grid \"" + grid.name + "\"", "a grid with active voxels to render");
  CloudImportOptions opt;
  opt.medium = default_medium(grid);
  opt.tau_tolerance = tau_tolerance_for_error(a.error);
  progress.stage(1, "import");
  auto t = std::chrono::steady_clock::now();
  CloudImportReport rep;
  const std::vector<GaussianParticle> particles = import_cloud(grid, opt, &rep);
  const double import_seconds = seconds_since(t);

  const CameraDescription cam = framing_camera(grid);
  const CameraFrame frame = camera_frame(cam, a.width, a.height);
  SnapshotTiming timing;
  progress.stage(2, "splats");
  const RgbImage splat = render_particle_snapshot(particles, cam, a.width, a.height,
                                                  glm::vec3(opt.medium.background), 3, &timing);
  progress.stage(3, "reference");
  t = std::chrono::steady_clock::now();
  const std::vector<float> light = light_optical_depth(grid, opt.medium);
  const RgbImage ref = render_volume_reference(grid, light, frame, opt.medium);
  const double reference_seconds = seconds_since(t);
  const double rmse = image_rmse(ref, splat);

  // vdb_render, matched.
  const double voxel_length = std::cbrt(std::abs(grid.voxel_size[0] * grid.voxel_size[1] * grid.voxel_size[2]));
  const double sigma_voxel = opt.medium.extinction * voxel_length;
  const double scatter = sigma_voxel * opt.medium.albedo, absorb = sigma_voxel - scatter;
  const double fov_x = 2.0 * std::atan(std::tan(0.5 * glm::radians(double(cam.fov_y_deg))) * a.width / a.height);
  const std::filesystem::path tmp =
      std::filesystem::temp_directory_path() / ("pyro_bench_vdb_" + std::to_string(::getpid()) + ".ppm");
  const glm::dvec3 to_light = -glm::normalize(opt.medium.light_direction);
  std::string grid_option;
  if (!a.grid.empty()) grid_option = " -name '" + a.grid + "'";
  const std::string cmd =
      a.vdb_render + " '" + a.file + "' '" + tmp.string() + "'" + grid_option + " -res " +
      std::to_string(a.width) + "x" + std::to_string(a.height) + " -translate " +
      vec(glm::dvec3(cam.position)) + " -lookat " + vec(glm::dvec3(cam.target)) + " -up " +
      vec(glm::dvec3(cam.up)) + " -fov " + std::to_string(glm::degrees(fov_x)) + " -absorb " +
      vec(glm::dvec3(absorb)) + " -scatter " + vec(glm::dvec3(scatter)) + " -light " +
      vec(to_light) + "," + vec(opt.medium.light_color) + " -gain 0 -step 0.5 -shadowstep 1" +
      " -cpus 0 > /dev/null 2>&1";
  progress.stage(4, "vdb_render");
  t = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  progress.update(5);
  progress.finish();
  const double vdb_render_seconds = seconds_since(t);
  std::error_code ec;
  std::filesystem::remove(tmp, ec);
  const bool vdb_ok = status == 0;
  if (!vdb_ok) std::fprintf(stderr, "pyro bench vdb: vdb_render failed (status %d): %s\n", status, cmd.c_str());

  nlohmann::json j = {{"file", a.file},
                      {"width", a.width},
                      {"height", a.height},
                      {"active_voxels", rep.active_voxels},
                      {"particles", rep.particles},
                      {"import_seconds", import_seconds},
                      {"splat_ms", timing.render_seconds * 1e3},
                      {"reference_ms", reference_seconds * 1e3},
                      {"vdb_render_ms", vdb_ok ? vdb_render_seconds * 1e3 : -1.0},
                      {"speedup_vs_vdb_render", vdb_ok ? vdb_render_seconds / timing.render_seconds : 0.0},
                      {"speedup_vs_reference", reference_seconds / timing.render_seconds},
                      {"rmse_vs_reference", rmse},
                      {"vdb_render_command", cmd}};
  if (a.json)
    std::printf("%s\n", j.dump().c_str());
  else
    std::printf("splat %.1f ms, reference %.1f ms, vdb_render %.1f ms: %.1fx faster than vdb_render, "
                "RMSE %.4f\n",
                timing.render_seconds * 1e3, reference_seconds * 1e3, vdb_render_seconds * 1e3,
                vdb_render_seconds / timing.render_seconds, rmse);
}

}  // namespace

void add_bench_vdb_command(CLI::App& bench) {
  auto args = std::make_shared<BenchVdbArgs>();
  CLI::App* cmd = bench.add_subcommand("vdb", "Splatting vs the CPU reference vs OpenVDB's vdb_render on one view");
  cmd->add_option("file", args->file, "OpenVDB file (.vdb)")->required();
  cmd->add_option("--grid", args->grid, "Grid name");
  cmd->add_option("--grid-index", args->grid_index, "Grid position in the file, from 0");
  cmd->add_option("--error", args->error, "Import error target (default 0.03)");
  cmd->add_option("--width", args->width, "Image width (default 512)")->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Image height (default 512)")->check(CLI::Range(1, 8192));
  cmd->add_option("--vdb-render", args->vdb_render, "The vdb_render program (default: from PATH)");
  cmd->add_flag("--json", args->json, "Print a JSON summary");
  cmd->callback([args] { run_bench_vdb(*args); });
}

}  // namespace pyro::cli
