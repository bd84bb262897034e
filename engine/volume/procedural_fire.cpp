#include "engine/volume/procedural_fire.h"

#include <algorithm>
#include <cmath>

#include "engine/core/rng.h"

namespace pyro {

namespace {

// Three octaves of products of sines, phases from the seed: a smooth field in [0, 1], mostly
// 0.4 to 1.
struct Turbulence {
  double phase[3][3];
  explicit Turbulence(uint64_t seed) {
    uint64_t state = seed * 0x9e3779b97f4a7c15ull + 1;
    for (auto& octave : phase)
      for (double& p : octave) p = double(splitmix64(state) >> 11) * (6.283185307179586 / double(uint64_t{1} << 53));
  }
  double at(double x, double y, double z) const {
    double sum = 0.0, amplitude = 0.5, frequency = 1.0;
    for (const auto& p : phase) {
      sum += amplitude * std::sin(frequency * x + p[0]) * std::sin(frequency * y + p[1]) * std::sin(frequency * z + p[2]);
      amplitude *= 0.5;
      frequency *= 2.1;
    }
    return std::clamp(0.7 + 0.6 * sum, 0.0, 1.0);
  }
};

VdbGridToWrite grid_named(const char* name, const std::array<int, 3>& dims, const ProceduralFireOptions& o) {
  VdbGridToWrite g;
  g.name = name;
  g.dims = dims;  // index origin 0: the box starts on OpenVDB's 8^3 leaves (a smaller file)
  g.voxel_size = {o.voxel_size, o.voxel_size, o.voxel_size};
  g.translation = {-0.5 * dims[0] * o.voxel_size, 0.0, -0.5 * dims[2] * o.voxel_size};
  return g;
}

}  // namespace

std::vector<VdbGridToWrite> make_procedural_fire(const ProceduralFireOptions& o) {
  const std::array<int, 3> dims{o.width, o.width * 5 / 3, o.width};
  VdbGridToWrite density = grid_named("density", dims, o), temperature = grid_named("temperature", dims, o),
                 velocity = grid_named("velocity", dims, o);
  velocity.vec3 = true;
  const Turbulence noise(o.seed), billows(o.seed + 1);
  const double r0 = 0.5 * dims[0];
  const auto smoothstep = [](double a, double b, double x) {
    const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
  };
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) {
        const double dx = x - 0.5 * dims[0] + 0.5, dz = z - 0.5 * dims[2] + 0.5;
        const double h = (y + 0.5) / dims[1], d = std::hypot(dx, dz);
        const double r = r0 * (0.5 + 0.5 * h), erode = noise.at(0.45 * dx, 0.3 * y, 0.45 * dz);
        // Tongues: the flame's height varies around the axis as sines that change fast across and
        // slowly upward, so each reaches up as a streak.
        const double reach = 0.25 + 0.6 * (noise.at(0.9 * dx, 0.12 * y, 0.9 * dz) - 0.4);
        const double flame =
            std::exp(-std::pow(d / (0.75 * r), 2.0)) * (1.0 - smoothstep(reach - 0.12, reach + 0.02, h)) * erode;
        // The smoke's axis wanders; its radius grows linearly with height, as a buoyant plume's
        // does (Morton, Taylor & Turner 1956), its density thins as it spreads, and its top is
        // as ragged as its billows.
        const double ax = 0.12 * r0 * std::sin(5.0 * h + billows.phase[0][0]),
                     az = 0.12 * r0 * std::sin(4.0 * h + billows.phase[0][1]);
        const double rs = r0 * (0.2 + 0.3 * h), ds = std::hypot(dx - ax, dz - az);
        const double billow = billows.at(0.25 * dx, 0.2 * y, 0.25 * dz);
        const double top = h + 0.15 * (billow - 0.7);
        const double smoke = std::exp(-std::pow(ds / rs, 2.0)) * smoothstep(0.3, 0.55, h) * (1.0 - smoothstep(0.75, 1.0, top)) *
                             (0.35 * r0 / rs) * billow;
        double rho = (0.6 * std::exp(-std::pow(d / r, 2.0)) * flame + 0.9 * smoke) * erode * erode;
        double heat = std::min(1.0, 1.3 * flame);
        rho = rho < 0.02 ? 0.0 : rho;  // a fog volume's empty air
        heat = rho == 0.0 || heat < 0.01 ? 0.0 : heat;
        density.values.push_back(float(rho));
        temperature.values.push_back(float(o.kelvin && heat > 0.0 ? 300.0 + 1800.0 * heat : heat));
        const double swirl = rho == 0.0 ? 0.0 : 0.3;
        velocity.values.insert(velocity.values.end(), {float(-swirl * dz / r0), float(rho == 0.0 ? 0.0 : 1.0 + 2.0 * heat),
                                                       float(swirl * dx / r0)});
      }
  std::vector<VdbGridToWrite> grids{density, temperature};
  if (o.velocity) grids.push_back(velocity);
  return grids;
}

std::vector<VdbGridToWrite> make_uniform_fire_box(double kelvin) {
  constexpr int kSide = 16, kMargin = 2;
  VdbGridToWrite density, temperature;
  density.name = "density";
  temperature.name = "temperature";
  for (VdbGridToWrite* g : {&density, &temperature}) {
    g->dims = {kSide, kSide, kSide};
    g->voxel_size = {0.1, 0.1, 0.1};
  }
  const auto inside = [](int i) { return i >= kMargin && i < kSide - kMargin; };
  for (int z = 0; z < kSide; ++z)
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x) {
        const bool in = inside(x) && inside(y) && inside(z);
        density.values.push_back(in ? 1.0f : 0.0f);
        temperature.values.push_back(in ? float(kelvin) : 0.0f);
      }
  return {density, temperature};
}

}  // namespace pyro
