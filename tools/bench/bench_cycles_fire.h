#pragma once
// pyro bench cycles-fire FILE...: a fire cache as the engine shows it, against Blender's Cycles
// rendering the same grids with its own black-body colour (tools/bench/cycles_render.h).
//
// For each VDB file with a temperature grid (engine/io/vdb_temperature_grid.h):
// - The engine's frame: a scene drawing the file as the `vdb` template does (its particles
//   imported on load at the error target, its fire mapped to kelvin and exposed by default,
//   docs/vdb_import.md), placed at its own coordinates and seen from its framing camera, with
//   nothing lit but the fire (sun, ambient and sky black): the light the fire emits, seen through
//   its smoke.
// - Cycles' frame: the density grid, the temperature in kelvin, and the emission's luminance per
//   unit length (extinction x density x the luminance of the engine's L_e(T), Max 1995: emission
//   goes with extinction) written again in leaf voxels; Cycles emits its Blackbody node's colour
//   at that luminance, absorbs with the same extinction and scatters nothing.
// - Both are scored over the emitting pixels (Cycles' luminance at least `emitting_fraction` of
//   its largest): the CIE 1931 xy chromaticity of their summed light, each pixel's xy, and each
//   pixel's luminance relative to the mean over them.
// - The template itself (content/templates/vdb.json with the file in it, at its own size, lit by
//   its daylight): how many pixels have a channel past the display's white.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "systems/runtime/reference/rgb_image.h"

namespace pyro {

struct CyclesFireBenchOptions {
  std::vector<std::string> files;
  int width = 160, height = 120;
  int cycles_samples = 64;          // emission and absorption only: the ray march's jitter is the noise
  double error = 0.03;              // the import's target, as the vdb template's
  double emitting_fraction = 0.05;  // of Cycles' largest luminance
  std::string blender = "blender";
  ProgressSink* progress = nullptr;
  std::function<void(const std::string&)> on_note;
};

// Fields: blender, width, height, cycles_samples, error, emitting_fraction, files [{file,
// temperature_grid, hottest_kelvin, extinction, emitting_pixels, chromaticity_ours [x, y],
// chromaticity_cycles [x, y], chromaticity_difference, pixel_chromaticity_difference_median,
// pixel_chromaticity_difference_p90, relative_luminance_rmse, cycles_seconds,
// template_clipped_pixels, template_pixels}]. Cycles' fields are null when its run failed (a
// note says why). Throws UserError naming the file when it has no temperature grid, or a grid
// with a rotated or non-uniform voxel transform; without the blender program nothing runs.
nlohmann::json bench_cycles_fire(const CyclesFireBenchOptions& options);

// The scores of `ours` against `cycles` (the same size, linear RGB) over the pixels where Cycles'
// luminance is at least `emitting_fraction` of its largest: emitting_pixels, and unless no pixel
// or no light of ours is there, chromaticity_ours, chromaticity_cycles, chromaticity_difference,
// pixel_chromaticity_difference_median and _p90, relative_luminance_rmse (fields as above).
nlohmann::json score_fire_against_cycles(const RgbImage& ours, const RgbImage& cycles, double emitting_fraction);

}  // namespace pyro
