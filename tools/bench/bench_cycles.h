#pragma once
// pyro bench cycles FILE...: the path-traced truth (systems/runtime/reference/path_traced_volume.h)
// against an independent path tracer, Blender's Cycles, run headless through
// content/cycles/render_volume.py (the conventions it converts, and how they were checked, are in
// its header). Each grid is written again with its density in leaf voxels (Cycles shows nothing
// of density kept in OpenVDB's active tiles), lit by the sun from `directions` directions
// (tools/bench/sun_directions.h), seen from its framing camera, with a black sky.
// Without the blender program nothing runs (UserError); a Cycles run that fails is a note, and
// its direction has no score.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"

namespace pyro {

struct CyclesBenchOptions {
  std::vector<std::string> files;
  std::string grid;          // "" : each file's first float grid
  int directions = 3;
  int width = 128, height = 128;
  int samples = 512;         // paths per pixel of the engine's path tracer
  int cycles_samples = 512;  // samples per pixel of each Cycles render (two renders a direction)
  int bounces = 256;         // Cycles' volume bounces (the engine's paths are not cut)
  double albedo = 0.95;
  double anisotropy = 0.6;
  int block = 8;             // side of the square blocks of pixels whose means are scored too
  double offset_ours = 0.0;  // added to the engine's image where the medium shows (a known bias)
  std::string blender = "blender";
  int threads = 0;
  ProgressSink* progress = nullptr;
  std::function<void(const std::string&)> on_note;
};

// Fields: blender, width, height, samples, cycles_samples, bounces, albedo, anisotropy, block,
// offset_ours, files [{file, grid, extinction, directions [{direction, path_traced_seconds,
// monte_carlo_error, cycles_seconds, cycles_noise, noise_rmse, rmse_vs_cycles,
// block_rmse_vs_cycles, block_noise_rmse, bias_rmse, mean_difference, mean_difference_error}],
// max_rmse_vs_cycles, max_bias_rmse}].
//  - cycles_noise: the RMSE between two Cycles renders with different seeds over √2, the noise of
//    one; noise_rmse = √(monte_carlo_error² + cycles_noise²), the RMSE noise alone would give.
//  - The block fields score the means of block × block pixels over the blocks where the medium
//    shows in the path tracer's image (tools/bench/block_scoring.h): their noise is the path
//    tracer's (its pixels are independent: independent_block_noise) and Cycles' (its block means'
//    difference over √2); bias_rmse is what that noise leaves unexplained.
//  - mean_difference: ours minus Cycles' over the pixels where the medium shows, with its
//    standard error (medium_mean_difference): a bias of one sign.
//  - offset_ours, added to each channel of the engine's image where it differs from the
//    background, shows how small a bias those scores see.
// A direction whose Cycles run failed has null in its Cycles fields. Throws UserError naming the
// file for a grid without active voxels or with a rotated or non-uniform voxel transform (the
// leaf copy is written with a uniform voxel size and a translation).
nlohmann::json bench_cycles(const CyclesBenchOptions& options);

}  // namespace pyro
