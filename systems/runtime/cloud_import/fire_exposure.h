#pragma once
// How a volume's fire and its smoke look unless a scene says otherwise.
//
// Exposure. A fire cache's grids carry no brightness that a display can use: a dense hot core
// emits up to the full black-body radiance, so at a fixed intensity a thick fire saturates to a
// white disc while a thin one barely glows. The intensity is instead chosen from the volume
// itself: the brightest line of sight through it, at intensity 1, is measured from each of six
// sides, and the intensity set so that the median of the six (the mean of the third and fourth
// brightest) reaches kFireExposure. The median is a typical view: a column of flame seen along
// its length, from above or below, is brighter than from any of its four sides, and a fire is
// mostly seen from its sides. Two measures:
// - the grid's own lines: every axis-aligned line of voxels, seen from either end, each voxel a
//   homogeneous segment of optical depth t = sigma_t * (voxel length along the line) that adds
//   L_e (1 - e^-t) and dims what lies behind it by e^-t (Max 1995, "Optical models for direct
//   volume rendering", section 2, absorption plus emission, integrated exactly over a segment of
//   constant coefficients). pyro import-vdb exposes with it, before it fits the particles.
// - the particles' lines, when they are what is drawn: the brightest pixel of the particles,
//   emitting alone against black, seen from the six views around the grid by the CPU reference.
//   Particles coarser than the grid average the temperature over their support, and a black
//   body's luminance falls steeply with it (Planck), so the drawn fire can be several times
//   dimmer than the grid's hottest lines; a scene's VDB volume, imported on load, exposes so.
//
// Smoke. The smoke around a fire is soot, much darker than a cloud's water droplets: a cloud's
// albedo 0.9 lit by a daylight sun shows as white smoke that the fire's light is lost in.
// Blender's Principled Volume, which Mantaflow fire caches are rendered with, defaults to a
// scattering colour of 0.5; a volume with fire takes that albedo by default.
#include <vector>

#include "engine/math/temperature_emission.h"

#include "engine/particles/gaussian_particle.h"
#include "engine/volume/dense_grid.h"

namespace pyro {

// The largest channel of the brightest line of sight, in linear radiance, at the exposed
// intensity: under the display's white with room for a sky or a lit smoke behind it.
inline constexpr double kFireExposure = 0.45;
// The exposed intensity never exceeds this: a fire too thin or too cool to reach kFireExposure
// at it glows as it is rather than having its faintest wisps raised to a flame.
inline constexpr double kMaxExposedIntensity = 100.0;
// The albedo of a fire's smoke (see above).
inline constexpr double kFireSmokeAlbedo = 0.5;

// The largest channel of the emitted radiance along the brightest axis-aligned line of sight,
// from each end of each axis, the median of the six, through `density` (extinction `extinction` per world unit per unit value), whose voxels emit
// emitted_radiance(emission, temperature) (`temperature`: the same box and layout as `density`).
// 0 when nothing emits.
double brightest_fire_sightline(const DenseGrid& density, double extinction, const DenseGrid& temperature,
                                const TemperatureEmission& emission);

// The largest channel of the brightest pixel, the median over the six views, of `particles`
// (world coordinates of `grid`, each
// particle's colour its emitted radiance, nothing else lighting them) seen from views_around(grid)
// (grid_framing.h) at `resolution` pixels square against black (particle_reference.h).
double brightest_particle_sightline(const GridHeader& grid, const std::vector<GaussianParticle>& particles,
                                    int resolution = 64, int threads = 0);

// The intensity that brings a line of sight of radiance `brightest` at intensity 1 to
// kFireExposure, at most kMaxExposedIntensity; kDefaultEmissionIntensity when nothing glows.
double exposure_for_sightline(double brightest);

// The intensity (engine/math/temperature_emission.h) at which the brightest line of sight reaches
// kFireExposure, at most kMaxExposedIntensity; kDefaultEmissionIntensity when nothing glows.
// `mapping` turns the temperature grid's values into kelvin.
double exposed_fire_intensity(const DenseGrid& density, double extinction, const DenseGrid& temperature,
                              const TemperatureMapping& mapping);

}  // namespace pyro
