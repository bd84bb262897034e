#pragma once
// pyro bench cycles-scene SCENE --frame N: one whole frame of a scene, as the engine draws it,
// against Blender's Cycles rendering the same frame (content/cycles/render_scene.py, whose
// header holds the conventions): the meshes with their albedo, the media voxelised as
// `pyro export-vdb` writes them, every sun, the ambient term as Cycles' world, the background
// seen by camera rays. Both frames are scored as every accuracy figure scores images
// (engine/math/image_error.h: linear RGB, highlights rolled off, clamped to [0, 1]), and the
// frame also sRGB-encoded as its PNG holds it: the RMSE over the frame
// and over each region (frame_regions.h: media, surfaces in the key light, surfaces in shadow,
// sky), each beside Cycles' own noise (two renders of different seeds: their RMSE over √2; the
// engine draws without noise). Without the blender program nothing runs (UserError, after the
// output gate); a Cycles run that fails is a note, and the frame has no score.
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"

namespace pyro {

struct CyclesSceneBenchOptions {
  std::string scene;
  int frame = 0;
  int width = 0, height = 0;   // 0: the scene's aspect, 240 pixels on its longer side
  int samples = 256;           // Cycles' samples per pixel, each of two renders
  int bounces = 64;            // Cycles' volume bounces
  double voxel_error = 0.01;   // the media grid's column opacity error target
  std::string image;           // a PNG of the engine's frame, Cycles' and the regions side by side; "": none
  std::string blender = "blender";
  int threads = 0;
  ProgressSink* progress = nullptr;
  std::function<void(const std::string&)> on_note;
};

// Fields: scene, frame, width, height, samples, bounces, particles, voxel_size, voxel_error,
// approximations [text], engine_seconds, cycles_seconds, rmse, srgb_rmse, cycles_noise,
// largest_region, regions {name: {pixels, share, rmse, cycles_noise, mean_difference,
// squared_error_share}}. The Cycles fields are null when its run failed. largest_region names the
// region holding the largest share of the frame's squared error.
nlohmann::json bench_cycles_scene(const CyclesSceneBenchOptions& options);

}  // namespace pyro
