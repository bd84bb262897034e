#pragma once
// pyro bench multiple-scattering FILE: how far single scattering and the octave approximation of
// multiple scattering (engine/math/scattering_octaves.h) fall from the path-traced truth
// (systems/runtime/reference/path_traced_volume.h), for an OpenVDB grid lit by the sun from `directions`
// directions (tools/bench/sun_directions.h) and seen from its framing camera.
// Both approximations are the ray-marched grid (systems/runtime/reference/volume_reference.h) with exact
// shadow depths, so what differs from the truth is the light scattered more than once and
// nothing else. The sky is black (ambient 0): the sun is the only light.
// The engine's own frames are scored too: the grid imported once as particles that keep their
// albedo and lit by the light phase (docs/lighting.md) with the single-scattering lobe and with
// the octaves.
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "components/shadow_settings.h"
#include "engine/core/progress_sink.h"
#include "engine/math/scattering_octaves.h"

namespace pyro {

struct MultipleScatteringBenchOptions {
  std::string file, grid;
  int grid_index = -1;
  int directions = 3;
  int width = 128, height = 128;
  int samples = 64;         // paths per pixel of the truth
  double extinction = 0.0;  // per world unit per unit density; 0: the grid's default
  double albedo = 0.95;
  SunScattering sun{0.6, {4, 0.25, 0.5, 0.5}};  // the approximation's lobe and octaves
  double error = 0.03;      // the import's error target (as a scene's volume)
  ShadowMethod shadow_method = ShadowMethod::shadow_map;  // the engine's
  std::string images;       // a folder for the frames as PNG ("": none)
  int threads = 0;
  ProgressSink* progress = nullptr;
  std::function<void(const std::string&)> on_note;
};

// Fields: file, grid, width, height, samples, extinction, albedo, anisotropy, octaves {count,
// attenuation, contribution, eccentricity}, directions [{direction, path_traced_seconds,
// monte_carlo_error, single_scattering_rmse, octaves_rmse, octaves_seconds, engine_single_rmse,
// engine_octaves_rmse}], particles, max_single_scattering_rmse, max_octaves_rmse,
// octaves_closer_everywhere, engine_octaves_closer_everywhere. Throws UserError
// naming the file for a grid without active voxels, or for octave parameters out of range.
nlohmann::json bench_multiple_scattering(const MultipleScatteringBenchOptions& options);

}  // namespace pyro
