#include "tools/bench/cycles_render.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/vdb_reader.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

// Nine significant digits, never in exponent form when negative: Python's argparse takes
// "-2.4e-07" for an option (it knows negative numbers only as -D, -D.D or -.D).
std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  if (v < 0.0 && std::string(buf).find('e') != std::string::npos) std::snprintf(buf, sizeof buf, "%.17f", v);
  return buf;
}

std::string spaced_vector(const glm::dvec3& v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }

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

// The script's command line for `r`, writing `out`.
std::string cycles_command(const CyclesRequest& r, const fs::path& out) {
  const VolumeMedium& m = r.medium;
  std::vector<std::pair<const char*, std::string>> args = {
      {"--vdb", shell_quoted(r.vdb)},
      {"--grid", shell_quoted(r.grid)},
      {"--extinction", num(m.extinction)},
      {"--albedo", num(m.albedo)},
      {"--anisotropy", num(r.anisotropy)},
      {"--sun-direction", spaced_vector(m.light_direction)},
      {"--light-color", spaced_vector(m.light_color)},
      {"--background", spaced_vector(m.background)},
      {"--camera-position", spaced_vector(glm::dvec3(r.camera.position))},
      {"--camera-target", spaced_vector(glm::dvec3(r.camera.target))},
      {"--camera-up", spaced_vector(glm::dvec3(r.camera.up))},
      {"--fov-y", num(r.camera.fov_y_deg)},
      {"--width", std::to_string(r.width)},
      {"--height", std::to_string(r.height)},
      {"--samples", std::to_string(r.samples)},
      {"--bounces", std::to_string(r.bounces)},
      {"--seed", std::to_string(r.seed)},
      {"--out", shell_quoted(out.string())}};
  if (!r.temperature_grid.empty()) {
    args.emplace_back("--temperature-grid", shell_quoted(r.temperature_grid));
    args.emplace_back("--emission-grid", shell_quoted(r.emission_grid));
  }
  std::string cmd = blender_script_command(r.blender, "cycles/render_volume.py");
  for (const auto& [flag, value] : args) cmd += std::string(" ") + flag + " " + value;
  return cmd;
}

}  // namespace

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

bool program_exists(const std::string& program) {
  if (program.find('/') != std::string::npos) return access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
  return false;
}

CyclesRender run_cycles(const std::string& cmd, const fs::path& out, int width, int height, const fs::path& log,
                        const std::function<void(const std::string&)>& on_note) {
  const auto t = std::chrono::steady_clock::now();
  const int status = std::system((cmd + " > " + shell_quoted(log.string()) + " 2>&1").c_str());
  CyclesRender result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  if (status == 0) result.image = read_pfm(out, width, height);
  if (result.image.rgb.empty() && on_note) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    on_note("Cycles failed (status " + std::to_string(status) + "): " + cmd + "\n" + text.str().substr(0, 2000));
  }
  return result;
}

CyclesRender render_with_cycles(const CyclesRequest& r, const fs::path& scratch,
                                const std::function<void(const std::string&)>& on_note) {
  const fs::path out = scratch / ("cycles_" + std::to_string(r.seed) + ".pfm");
  return run_cycles(cycles_command(r, out), out, r.width, r.height, scratch / "cycles.log", on_note);
}

std::string blender_script_command(const std::string& blender, const std::string& script) {
  return shell_quoted(blender) + " -b --factory-startup --python " + shell_quoted(content_path(script)) + " --";
}

std::array<double, 3> axis_voxel_sizes(const GridHeader& grid) {
  const glm::dmat4& m = grid.index_to_world;
  bool along_axes = true;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) along_axes = along_axes && (c == r ? m[c][r] > 0.0 : m[c][r] == 0.0);
  if (!along_axes)
    throw UserError(grid.file, "grid \"" + grid.name + "\"",
                    "voxels scaled along the axes without rotation (the Cycles comparison writes the grid again so)");
  return {m[0][0], m[1][1], m[2][2]};
}

double uniform_voxel_size(const GridHeader& grid) {
  const std::array<double, 3> v = axis_voxel_sizes(grid);
  if (v[1] != v[0] || v[2] != v[0])
    throw UserError(grid.file, "grid \"" + grid.name + "\"",
                    "a uniform voxel size without rotation (the Cycles comparison writes the grid again so)");
  return v[0];
}

void write_leaf_copy(const DenseGrid& grid, const std::string& path) {
  const glm::dmat4& m = grid.index_to_world;
  const double v = uniform_voxel_size(grid);
  write_vdb_fog_volume(path, grid.name, grid.origin, grid.dims, grid.values, v, {m[3][0], m[3][1], m[3][2]});
}

}  // namespace pyro
