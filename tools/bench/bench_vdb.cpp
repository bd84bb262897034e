#include "tools/bench/bench_vdb.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "engine/core/stopwatch.h"
#include "engine/core/user_error.h"
#include "tools/import/fitted_import.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/gaussian_lighting.h"
#include "systems/runtime/cloud_import/grid_framing.h"
#include "systems/runtime/reference/rgb_image.h"
#include "systems/runtime/reference/volume_reference.h"
#include "systems/runtime/scene_runtime/anisotropic_snapshot.h"

namespace pyro {

namespace {

std::string comma_vector(const glm::dvec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.9g", v.x, v.y, v.z);
  return buf;
}

// vdb_render's command line for the grid seen by `cam` through `medium`, writing `image`.
std::string vdb_render_command(const VdbBenchOptions& a, const DenseGrid& grid,
                               const CameraDescription& cam, const VolumeMedium& medium,
                               const std::string& image) {
  const double voxel_length = std::cbrt(std::abs(grid.voxel_size[0] * grid.voxel_size[1] * grid.voxel_size[2]));
  const double sigma_voxel = medium.extinction * voxel_length;
  const double scatter = sigma_voxel * medium.albedo, absorb = sigma_voxel - scatter;
  const double fov_x = 2.0 * std::atan(std::tan(0.5 * glm::radians(double(cam.fov_y_deg))) * a.width / a.height);
  const glm::dvec3 to_light = -glm::normalize(medium.light_direction);
  std::string grid_option;
  if (!a.grid.empty()) grid_option = " -name '" + a.grid + "'";
  return a.vdb_render + " '" + a.file + "' '" + image + "'" + grid_option + " -res " +
         std::to_string(a.width) + "x" + std::to_string(a.height) + " -translate " +
         comma_vector(glm::dvec3(cam.position)) + " -lookat " + comma_vector(glm::dvec3(cam.target)) + " -up " +
         comma_vector(glm::dvec3(cam.up)) + " -fov " + std::to_string(glm::degrees(fov_x)) + " -absorb " +
         comma_vector(glm::dvec3(absorb)) + " -scatter " + comma_vector(glm::dvec3(scatter)) + " -light " +
         comma_vector(to_light) + "," + comma_vector(medium.light_color) + " -gain 0 -step " + std::to_string(a.vdb_render_step) +
         " -shadowstep " + std::to_string(a.vdb_render_shadow_step) +
         " -cpus 0 > /dev/null 2>&1";
}

// Runs `cmd`; its wall time in seconds, or a negative number when it failed.
double time_vdb_render(const std::string& cmd) {
  const auto t = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  const double seconds = seconds_since(t);
  return status == 0 ? seconds : -1.0 - status;
}

// vdb_render's binary PPM (P6, 8 bits): its film's linear values, each truncated to 8 bits
// (RayTracer.h's Film::convertToBitBuffer), so (byte + 0.5) / 255 undoes the truncation's
// half-step bias. Rows top first, as our images. Empty when the file is not such a PPM of the
// size asked for.
RgbImage read_vdb_render_ppm(const std::filesystem::path& path, int width, int height) {
  RgbImage img;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return img;
  int w = 0, h = 0, max = 0;
  const bool header = std::fscanf(f, "P6 %d %d %d", &w, &h, &max) == 3 && std::fgetc(f) != EOF;
  std::vector<unsigned char> bytes(size_t(3) * std::max(0, w) * std::max(0, h));
  const bool ok = header && w == width && h == height && max == 255 &&
                  std::fread(bytes.data(), 1, bytes.size(), f) == bytes.size();
  std::fclose(f);
  if (!ok) return img;
  img.width = w;
  img.height = h;
  img.rgb.resize(bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) img.rgb[i] = (float(bytes[i]) + 0.5f) / 255.0f;
  return img;
}

// The scene both renderers can model: vdb_render has no ambient light and a black background.
VolumeMedium without_ambient(VolumeMedium m) {
  m.ambient = glm::dvec3(0.0);
  m.background = glm::dvec3(0.0);
  return m;
}

// The splats and the CPU reference of the ambient-free medium against vdb_render's image.
nlohmann::json score_against_vdb_render(const DenseGrid& grid, const std::vector<GridGaussian>& fitted,
                                        const CameraDescription& cam, const std::vector<float>& light,
                                        const VolumeMedium& medium, const RgbImage& vdb) {
  const VolumeMedium unlit = without_ambient(medium);
  const RgbImage splat = render_anisotropic_snapshot(lit_world_gaussians(grid, fitted, unlit), cam, vdb.width,
                                                     vdb.height, glm::vec3(0.0f));
  const RgbImage ref = render_volume_reference(grid, light, camera_frame(cam, vdb.width, vdb.height), unlit);
  return {{"splats", image_rmse(splat, vdb)},
          {"reference", image_rmse(ref, vdb)},
          {"splats_vs_reference", image_rmse(splat, ref)}};
}

}  // namespace

nlohmann::json bench_vdb(const VdbBenchOptions& a) {
  ProgressTask progress(a.progress, "bench vdb", 5);
  progress.stage(0, "read");
  std::string note;
  const DenseGrid grid = read_vdb_grid(a.file, {a.grid, a.grid_index}, &note);
  if (!note.empty() && a.on_note) a.on_note(a.file + ": " + note);
  if (grid.empty()) throw UserError(a.file, "grid \"" + grid.name + "\"", "a grid with active voxels to render");
  progress.stage(1, "import");
  auto t = std::chrono::steady_clock::now();
  // The import as import-vdb makes it (fitted to the error target from every side, 256^2 views).
  const VdbImportReference views = make_vdb_import_reference(grid, 256, 256, true);
  const FittedImport fit = import_to_target(grid, a.error, views);
  const double import_seconds = seconds_since(t);
  const VolumeMedium& medium = views.medium;

  const CameraDescription cam = framing_camera(grid);
  SnapshotTiming timing;
  progress.stage(2, "splats");
  const RgbImage splat = render_anisotropic_snapshot(fit.best.fitted, cam, a.width, a.height,
                                                     glm::vec3(medium.background), 3, &timing);
  progress.stage(3, "reference");
  t = std::chrono::steady_clock::now();
  const std::vector<float> light = light_optical_depth(grid, medium);
  const RgbImage ref = render_volume_reference(grid, light, camera_frame(cam, a.width, a.height), medium);
  const double reference_seconds = seconds_since(t);

  const std::filesystem::path image =
      std::filesystem::temp_directory_path() / ("pyro_bench_vdb_" + std::to_string(::getpid()) + ".ppm");
  const std::string cmd = vdb_render_command(a, grid, cam, medium, image.string());
  progress.stage(4, "vdb_render");
  const double vdb_render_seconds = time_vdb_render(cmd);
  const bool vdb_ok = vdb_render_seconds >= 0.0;
  if (!vdb_ok && a.on_note)
    a.on_note("vdb_render failed (status " + std::to_string(int(-1.0 - vdb_render_seconds)) + "): " + cmd);
  nlohmann::json scores = nullptr;
  if (vdb_ok) {
    const RgbImage vdb = read_vdb_render_ppm(image, a.width, a.height);
    if (vdb.rgb.empty() && a.on_note) a.on_note("vdb_render's image could not be read: " + image.string());
    if (!vdb.rgb.empty()) scores = score_against_vdb_render(grid, fit.best.grid_gaussians, cam, light, medium, vdb);
  }
  std::error_code ec;
  std::filesystem::remove(image, ec);
  progress.update(5);
  progress.finish();
  return {{"file", a.file},
          {"width", a.width},
          {"height", a.height},
          {"active_voxels", grid.active_voxels},
          {"particles", fit.best.fitted.size()},
          {"import_target_met", fit.target_met},
          {"import_rmse_views_max", fit.best.rmse_views_max},
          {"import_seconds", import_seconds},
          {"splat_ms", timing.render_seconds * 1e3},
          {"reference_ms", reference_seconds * 1e3},
          {"vdb_render_ms", vdb_ok ? vdb_render_seconds * 1e3 : -1.0},
          {"speedup_vs_vdb_render", vdb_ok ? vdb_render_seconds / timing.render_seconds : 0.0},
          {"speedup_vs_reference", reference_seconds / timing.render_seconds},
          {"rmse_vs_reference", image_rmse(ref, splat)},
          // Without ambient light, black behind (what vdb_render models): {splats, reference,
          // splats_vs_reference}; null when vdb_render failed.
          {"rmse_vs_vdb_render", scores},
          {"vdb_render_command", cmd}};
}

}  // namespace pyro
