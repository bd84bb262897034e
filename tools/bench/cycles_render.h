#pragma once
// One render by Blender's Cycles, run headless through content/cycles/render_volume.py (its
// header holds the conventions it converts and how they were checked): a VDB medium lit by one
// sun, seen by a pinhole camera, optionally glowing with Cycles' own black-body colour. The
// benchmarks that score the engine against Cycles (bench_cycles.h, bench_cycles_fire.h) share it.
#include <array>
#include <filesystem>
#include <functional>
#include <string>

#include "components/volume_medium.h"
#include "engine/volume/dense_grid.h"
#include "systems/runtime/reference/rgb_image.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

// `s` quoted for the shell.
std::string shell_quoted(const std::string& s);

// Whether `program` runs: a path to an executable file, or a name found on PATH.
bool program_exists(const std::string& program);

struct CyclesRequest {
  std::string blender = "blender";
  std::string vdb;                  // a file written by write_leaf_copy or write_leaf_grids
  std::string grid;                 // its density grid
  std::string temperature_grid;     // kelvin ("": no emission)
  std::string emission_grid;        // the emission's luminance per world unit (with temperature_grid)
  VolumeMedium medium;              // extinction, albedo, sun, its colour, the background
  double anisotropy = 0.0;          // Henyey-Greenstein g
  CameraDescription camera;
  int width = 128, height = 128;
  int samples = 512;                // per pixel
  int bounces = 0;                  // volume bounces
  int seed = 1;
};

struct CyclesRender {
  RgbImage image;  // linear radiance; empty when the run failed
  double seconds = 0.0;
};

// Renders into `scratch` (the image and Cycles' log). A failed run returns an empty image and
// tells `on_note` the command and the head of the log.
CyclesRender render_with_cycles(const CyclesRequest& request, const std::filesystem::path& scratch,
                                const std::function<void(const std::string&)>& on_note);

// The command line that runs content/`script` in Blender headless, up to its "--".
std::string blender_script_command(const std::string& blender, const std::string& script);

// Runs `command` (its output to `log`) and reads the colour PFM it writes at `out` (width x height).
// A failed run returns an empty image and tells `on_note` the command and the head of the log.
CyclesRender run_cycles(const std::string& command, const std::filesystem::path& out, int width, int height,
                        const std::filesystem::path& log, const std::function<void(const std::string&)>& on_note);

// The voxel size along each index axis of a grid whose index-to-world map is a scale along the
// axes and a translation. Throws UserError naming the grid's file for a rotated map (the Cycles
// comparisons write grids again so).
std::array<double, 3> axis_voxel_sizes(const GridHeader& grid);

// The same, for a map whose scale is also the same along every axis.
double uniform_voxel_size(const GridHeader& grid);

// The grid again, its tiles spread into leaf voxels (Cycles shows nothing of density kept in
// OpenVDB's active tiles), with the same voxel size and translation. Throws UserError naming the
// grid's file for a rotated or non-uniform voxel transform.
void write_leaf_copy(const DenseGrid& grid, const std::string& path);

}  // namespace pyro
