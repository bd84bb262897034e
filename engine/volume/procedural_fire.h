#pragma once
// The project's own fire: one frame of a smoke-and-fire plume laid out as a Blender/Mantaflow
// smoke cache frame is (grids "density", "temperature" and "velocity"), deterministic from a seed,
// made without OpenVDB (tools/make_sample_volume --fire writes it through engine/io/vdb_reader.h).
//
// Shape (y up): h in [0, 1] from the base to the top, d the distance from the axis, s(a, b, h)
// the smoothstep, e and b two fields of a few octaves of sines whose phases come from the seed
// (e fine, the flame's erosion; b coarse, the smoke's billows).
//  - The flame, in tongues: flame = exp(-(d / (0.75 r))^2) (1 - s(k - 0.12, k + 0.02, h)) e, with
//    r = r0 (0.5 + 0.5 h) and the reach k = 0.25 + 0.6 (e' - 0.4), e' the sines stretched upward
//    (fast across, slow along the axis), so each tongue reaches up as a streak. Mantaflow stores
//    heat normalised (about [0, 1]); here min(1, 1.3 flame).
//  - The smoke, a plume: about an axis that wanders by 0.12 r0, of radius r_s = r0 (0.2 + 0.3 h)
//    growing linearly with height as a buoyant plume's does (Morton, Taylor & Turner 1956),
//    thinning as it spreads: smoke = exp(-(d_s / r_s)^2) s(0.3, 0.55, h)
//    (1 - s(0.75, 1, h + 0.15 (b - 0.7))) (0.35 r0 / r_s) b, its top as ragged as its billows.
//  - density = (0.6 exp(-(d / r)^2) flame + 0.9 smoke) e^2, below 0.02 empty air; it never
//    reaches the box's sides.
// `kelvin` writes the temperature as 300 K + 1800 K x heat instead (a Houdini-like grid in
// kelvin). The velocity is the plume's rise, (0, 1 + 2 heat, 0) world units per second, with a
// swirl about the axis.
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

// A calibration volume for renderers of fire: a cube of density 1 at one temperature `kelvin`,
// 12 voxels on a side in a grid of 16 (voxel size 0.1, two empty voxels around it), as grids
// "density" and "temperature" (kelvin, so larger than 10). Every line of sight through it meets one
// temperature, so two renderers that agree on a black body's colour render it in that colour
// alone (pyro bench cycles-fire; tools/make_sample_volume --fire-box KELVIN writes it).
std::vector<VdbGridToWrite> make_uniform_fire_box(double kelvin);

}  // namespace pyro
