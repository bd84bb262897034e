#pragma once
// The data of `pyro chart NAME` (tools/pyro/command_chart.cpp), one function per chart, one file
// each (chart_<name>.cpp). Each measures through the same code as the matching bench or analyze
// command, so its points agree with their figures. Sizes are the charts' defaults; tests pass
// smaller ones.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "tools/charts/chart_table.h"

namespace pyro {

// Table size x quadrature rule x intervals (engine/math/footprint.h, as `pyro analyze
// footprint`): time to build the table against the error of the raw table, sampled bilinearly,
// against the erf closed form.
struct FootprintChartOptions {
  std::vector<int> sizes{8, 16, 32, 64, 128};
  std::vector<int> intervals{2, 4, 8, 16, 32};  // even, for Simpson's rule
  int sample_grid = 241;
  int repeats = 3;  // the table build is timed as the best of this many
};
ChartTable chart_footprint(const FootprintChartOptions& options);

// Explicit Euler against the engine's exponential integrator
// (systems/animation/particle_integrator.h) as the step grows, against the exact solution.
struct IntegratorChartOptions {
  std::vector<double> steps{1.0 / 480, 1.0 / 240, 1.0 / 120, 1.0 / 60, 1.0 / 30,
                            1.0 / 15,  0.125,     0.25,      0.5};
  double horizon = 2.0;  // seconds simulated; each step divides it
  double drag = 10.0;    // k (1/s): explicit Euler is unstable for k dt > 2
  int particles = 1000;  // particles stepped per timing (time per particle is reported)
};
ChartTable chart_integrators(const IntegratorChartOptions& options);

// Viewplane, viewpoint and spherical billboards on scenes, against the CPU reference.
struct BillboardModesChartOptions {
  std::vector<std::string> scenes;  // empty: clouds, fog and explosion from content/scenes
  int width = 160, height = 120;
  int frames = 5;  // timed frames per mode
};
ChartTable chart_billboard_modes(const BillboardModesChartOptions& options);

// The shadow methods (systems/shadowing: none, rays, the map at each size) on lit scenes, against
// the CPU reference with exact shadows.
struct ShadowsChartOptions {
  std::vector<std::string> scenes;  // empty: clouds, fog and cloud_fitted from content/scenes, with
                                    // shadows on (a lit scene keeps its lobe and octaves)
  std::vector<int> map_sizes{16, 32, 64, 128, 256};
  int width = 160, height = 120;
  int frames = 5;  // timed frames per setting
};
ChartTable chart_shadows(const ShadowsChartOptions& options);

// The same methods on content/scenes/clouds.json's cumulus with 10,000 particles at each density
// (`pyro chart shadows --density`): the error against the reference as the optical depth across
// one particle grows, each row's extra columns its density and tau0; the summary names, per
// setting, the first density whose error exceeds `target` (null: none does).
struct ShadowDensityChartOptions {
  std::vector<double> densities{0.4, 0.7, 0.9, 0.99, 1.0};  // ascending
  std::vector<int> map_sizes{32, 64, 128};
  int width = 160, height = 90;
  int frames = 5;  // timed frames per setting
  double target = 0.03;
};
ChartTable chart_shadow_density(const ShadowDensityChartOptions& options);

// The octave approximation of multiple scattering (engine/math/scattering_octaves.h) with each
// count of octaves, drawn by the engine's lit splats (a grid imported once, relit by the light
// phase) and timed, against the path-traced truth of the grid
// (systems/runtime/reference/path_traced_volume.h), lit by the sun alone.
struct ScatteringChartOptions {
  std::string file;  // empty: content/volumes/sample_cloud.vdb
  std::vector<int> octaves{1, 2, 3, 4, 6, 8};
  double albedo = 0.95, anisotropy = 0.6;
  int width = 160, height = 160;
  int samples = 512;  // paths per pixel of the truth
  int frames = 8;     // timed frames per setting
};
ChartTable chart_scattering(const ScatteringChartOptions& options);

// Explosion media layers at 1, 1/2, 1/4, 1/8 with each upsampling method (`pyro bench layers`).
struct LayerResolutionChartOptions {
  // Empty: content/scenes/explosion.json (the paper's view) and explosion_behind_tower.json (the
  // tower in front of the explosion: depth edges across the media).
  std::vector<std::string> scenes;
  int width = 256, height = 256;
  int frames = 16;
  int error_frames = 4;
};
ChartTable chart_layer_resolution(const LayerResolutionChartOptions& options);

// VDB import error targets -> particles, render time, image error (`pyro import-vdb`).
struct ParticleBudgetChartOptions {
  std::vector<std::string> files;  // empty: the sample cloud, and the Disney cloud when present
  std::vector<double> error_targets{0.01, 0.02, 0.03, 0.05, 0.08, 0.12};
  int width = 128, height = 128;
  int repeats = 3;  // the splat render is timed as the best of this many
};
ChartTable chart_particle_budget(const ParticleBudgetChartOptions& options);

// Flipbook in-between frames (tools/charts/chart_flipbook_blend.cpp): for each count of frames
// per loop, the fire scene baked as an atlas with motion vectors at twice the frames; linear and
// motion-vector blends of neighbouring even frames at t = 0.5 against the odd frame between them.
// "time" is the frame count, "error" the RMSE.
struct FlipbookBlendChartOptions {
  std::string scene;  // empty: content/scenes/flipbook_fire.json
  std::vector<int> frames_per_loop{8, 16, 32};
  double loop_seconds = 16.0 / 30.0;
  int width = 64, height = 96;
  bool border_fade = false;  // the bake's border fade (FrameFade) on the frames
};
ChartTable chart_flipbook_blend(const FlipbookBlendChartOptions& options);

// ms per frame against particles, log-log (`pyro bench scale`): not a time-against-error chart,
// so it has its own CSV (particles, ms_per_frame, cpu_ms_per_frame and the stages; the fitted
// slopes in comment lines), drawn by tools/plots/plot_scale.py.
struct ScaleChartOptions {
  std::string scene;  // empty: content/scenes/clouds.json
  std::vector<uint64_t> counts{10000, 30000, 100000, 300000, 1000000, 2000000};
  int frames = 3;
  int width = 0, height = 0;  // 0: the scene's
  ProgressSink* progress = nullptr;
};
struct ScaleChart {
  std::string csv;
  nlohmann::json bench;  // pyro bench scale's result
};
ScaleChart chart_scale(const ScaleChartOptions& options);

// "footprint", "billboard-modes", "layer-resolution", "particle-budget", "integrators",
// "flipbook-blend", "scale".
std::vector<std::string> chart_names();

}  // namespace pyro
