#pragma once
// The project's own fire: one frame of a smoke-and-fire plume laid out as a Blender/Mantaflow
// smoke cache frame is (grids "density", "temperature" and "velocity"), deterministic from a seed,
// made without OpenVDB (tools/make_sample_volume --fire writes it through engine/io/vdb_reader.h).
//
// Shape (y up): a column whose radius widens with height, r(h) = r0 (0.5 + 0.5 h), h in [0, 1]
// from the base to the top, d the distance from the axis, s(a, b, h) the smoothstep. The flame
// fills the lower half, hottest on the axis: flame = exp(-(d / (0.75 r))^2) (1 - s(0.05, 0.6, h)) e,
// e a few octaves of sines whose phases come from the seed; Mantaflow stores heat normalised
// (about [0, 1]), here min(1, 1.3 flame). The density is the flame's soot and the smoke above it,
// which rises from h = 0.3 and thins out at the top: density = exp(-(d / r)^2) (0.6 flame +
// 0.9 s(0.3, 0.7, h) (1 - s(0.85, 1, h))) e^2, below 0.02 empty air. `kelvin` writes the
// temperature as 300 K + 1800 K x heat instead (a Houdini-like grid in kelvin). The velocity is
// the plume's rise, (0, 1 + 2 heat, 0) world units per second, with a swirl about the axis.
#include <cstdint>
#include <vector>

#include "engine/io/vdb_reader.h"

namespace pyro {

struct ProceduralFireOptions {
  uint64_t seed = 1;
  int width = 20;           // voxels across (x and z); the height is width * 5 / 3
  double voxel_size = 0.1;
  bool kelvin = false;      // temperature in kelvin rather than normalised heat
  bool velocity = true;     // write the velocity grid (vec3s) too
};

// The grids, in the order a Mantaflow cache frame lists them: density, temperature, velocity.
// The base's centre is at the world origin (index box from 0, translated).
std::vector<VdbGridToWrite> make_procedural_fire(const ProceduralFireOptions& options = {});

}  // namespace pyro
