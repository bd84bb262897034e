#include "systems/runtime/reference/path_traced_volume.h"

#include <chrono>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "engine/core/rng.h"
#include "engine/math/phase_function.h"
#include "systems/runtime/reference/grid_sampling.h"
#include "systems/runtime/reference/parallel_rows.h"
#include "systems/runtime/reference/pixel_ray.h"
#include "systems/runtime/reference/volume_reference.h"

namespace pyro {

namespace {

// Doubles in [0, 1) from SplitMix64 (engine/core/rng.h): 53 random bits each, as deep paths need
// more resolution than the engine's 24-bit floats.
struct Random {
  uint64_t state;
  double uniform() { return double(splitmix64(state) >> 11) * 0x1.0p-53; }
};

// The trilinear density at a local index position, from the dense array or the sparse bricks.
struct DenseDensity {
  const DenseGrid& g;
  float operator()(const glm::dvec3& p) const {
    const int n[3] = {g.dims[0], g.dims[1], g.dims[2]};
    return sample_trilinear(g.values.data(), n, p.x, p.y, p.z);
  }
};
struct SparseDensity {
  const SparseGrid& g;
  float operator()(const glm::dvec3& p) const { return sample_trilinear_sparse(g, p.x, p.y, p.z); }
};

// The density field in the grid's local index space, with the world-to-index map: a world ray
// (o, w) is the index-space line o + t M w, t in world units.
template <class Density>
struct GridField {
  Density density;
  double lo[3], hi[3];
  glm::dmat3 to_index;
  double max_density;

  // World distance from p to where the line leaves the sampled box (0 when outside it).
  double exit_distance(const glm::dvec3& p, const glm::dvec3& v) const {
    const double o[3] = {p.x, p.y, p.z}, d[3] = {v.x, v.y, v.z};
    double t0, t1;
    return intersect_box(o, d, lo, hi, t0, t1) ? std::max(t1, 0.0) : 0.0;
  }
};

// Delta tracking: world distance to the next real collision from p along v = M w, or −1 when the
// path leaves the grid first. sigma_bar: the majorant extinction per world unit.
template <class Density>
double free_path(const GridField<Density>& g, const glm::dvec3& p, const glm::dvec3& v, double sigma_bar,
                 Random& rng) {
  const double end = g.exit_distance(p, v);
  for (double t = 0.0;;) {
    t -= std::log1p(-rng.uniform()) / sigma_bar;
    if (t >= end) return -1.0;
    if (rng.uniform() * g.max_density < g.density(p + t * v)) return t;
  }
}

// Ratio tracking: an unbiased estimate of the transmittance from p to the grid's edge along v.
template <class Density>
double transmittance(const GridField<Density>& g, const glm::dvec3& p, const glm::dvec3& v, double sigma_bar,
                     Random& rng) {
  const double end = g.exit_distance(p, v);
  double T = 1.0;
  for (double t = 0.0; T > 1e-7;) {
    t -= std::log1p(-rng.uniform()) / sigma_bar;
    if (t >= end) break;
    T *= 1.0 - g.density(p + t * v) / g.max_density;
  }
  return T;
}

// A unit direction whose cosine with w is drawn from Henyey–Greenstein (Frisvad 2012's basis
// about w, in the branchless form of Duff et al. 2017).
glm::dvec3 scatter_direction(const glm::dvec3& w, double g, Random& rng) {
  const double mu = sample_henyey_greenstein_cosine(g, rng.uniform());
  const double phi = 2.0 * std::numbers::pi * rng.uniform();
  const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  const double sign = std::copysign(1.0, w.z), a = -1.0 / (sign + w.z), b = w.x * w.y * a;
  const glm::dvec3 t1(1.0 + sign * w.x * w.x * a, sign * b, -sign * w.x);
  const glm::dvec3 t2(b, sign + w.y * w.y * a, -w.y);
  return glm::normalize(mu * w + s * (std::cos(phi) * t1 + std::sin(phi) * t2));
}

template <class Density>
struct PathTracer {
  GridField<Density> field;
  const VolumeMedium& medium;
  const PathTraceOptions& options;
  glm::dvec3 eye;            // in index space
  glm::dvec3 to_light;       // unit, world: towards the sun
  glm::dvec3 sun_radiance;   // albedo x irradiance 4π light_color
  double sigma_bar;          // extinction x max density, per world unit

  struct Path {
    glm::dvec3 radiance{0.0};
    int scattering = 0;
    bool truncated = false;
  };

  // The radiance along the camera ray w (world, unit) from the eye.
  Path trace(glm::dvec3 w, Random& rng) const {
    Path out;
    glm::dvec3 p = eye, v = field.to_index * w;
    {
      const double o[3] = {p.x, p.y, p.z}, d[3] = {v.x, v.y, v.z};
      double t0, t1;
      if (!intersect_box(o, d, field.lo, field.hi, t0, t1) || t1 <= 0.0) {
        out.radiance = medium.background;
        return out;
      }
      p += std::max(t0, 0.0) * v;
    }
    const glm::dvec3 light_v = field.to_index * to_light;
    double weight = 1.0;
    for (;;) {
      const double t = field.max_density > 0.0 ? free_path(field, p, v, sigma_bar, rng) : -1.0;
      if (t < 0.0) {
        out.radiance += weight * (out.scattering == 0 ? medium.background : medium.ambient);
        return out;
      }
      p += t * v;
      ++out.scattering;
      const double mu = glm::dot(to_light, w);  // = the sun's travel against the way out, -w
      out.radiance += weight * sun_radiance * henyey_greenstein(mu, options.anisotropy) *
                      transmittance(field, p, light_v, sigma_bar, rng);
      if (options.max_scattering == 1) {  // single scattering: the ray march's unshadowed ambient
        out.radiance += weight * medium.albedo * medium.ambient;
        return out;
      }
      if (out.scattering >= options.max_scattering) {
        out.truncated = options.max_scattering > 1;
        return out;
      }
      weight *= medium.albedo;
      if (weight < 0.25) {  // Russian roulette: survive with probability 4 weight, then weigh 1/4
        if (rng.uniform() >= 4.0 * weight) return out;
        weight = 0.25;
      }
      w = scatter_direction(w, options.anisotropy, rng);  // μ = w_new · w, as the photon sees it
      v = field.to_index * w;
    }
  }
};

template <class Density>
PathTracedImage trace_image(const GridHeader& grid, Density density, double max_density, const CameraFrame& camera,
                            const VolumeMedium& medium, const PathTraceOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const glm::dmat4 to_local = world_to_local_index(grid);
  const PathTracer<Density> tracer{
      {density, {-1.0, -1.0, -1.0},
       {double(grid.dims[0]), double(grid.dims[1]), double(grid.dims[2])}, glm::dmat3(to_local), max_density},
      medium, options, glm::dvec3(to_local * glm::dvec4(glm::dvec3(camera.eye), 1.0)),
      -glm::normalize(medium.light_direction), medium.albedo * 4.0 * std::numbers::pi * medium.light_color,
      medium.extinction * max_density};
  PathTracedImage out;
  RgbImage& img = out.image;
  img.width = camera.width;
  img.height = camera.height;
  img.rgb.assign(size_t(3) * img.width * img.height, 0.0f);
  const int spp = std::max(1, options.samples_per_pixel);
  std::vector<double> variance(size_t(img.width) * img.height, 0.0);
  std::vector<uint64_t> events(img.height, 0), truncated(img.height, 0);
  parallel_rows(img.height, options.threads, [&](int y) {
    for (int x = 0; x < img.width; ++x) {
      Random rng{mix_seeds(options.seed, uint64_t(y) * img.width + x)};
      glm::dvec3 sum(0.0), sum2(0.0);
      for (int s = 0; s < spp; ++s) {
        const double jx = rng.uniform(), jy = rng.uniform();
        const typename PathTracer<Density>::Path path = tracer.trace(pixel_ray_direction(camera, x + jx, y + jy), rng);
        sum += path.radiance;
        sum2 += path.radiance * path.radiance;
        events[y] += uint64_t(path.scattering);
        truncated[y] += path.truncated ? 1 : 0;
      }
      const glm::dvec3 mean = sum / double(spp);
      float* px = img.at(x, y);
      for (int c = 0; c < 3; ++c) {
        px[c] = float(mean[c]);
        if (spp > 1)  // the variance of the mean: the sample variance over spp
          variance[size_t(y) * img.width + x] +=
              std::max(0.0, sum2[c] - spp * mean[c] * mean[c]) / (double(spp) * (spp - 1));
      }
    }
  });
  double v = 0.0;
  for (double pv : variance) v += pv;
  out.monte_carlo_error = std::sqrt(v / (3.0 * double(variance.size())));
  out.paths = uint64_t(spp) * img.width * img.height;
  for (int y = 0; y < img.height; ++y) {
    out.scattering_events += events[y];
    out.truncated_paths += truncated[y];
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

double largest(const std::vector<float>& values) {
  double m = 0.0;
  for (float v : values) m = std::max(m, double(v));
  return m;
}

}  // namespace

PathTracedImage path_trace_volume(const DenseGrid& grid, const CameraFrame& camera, const VolumeMedium& medium,
                                  const PathTraceOptions& options) {
  return trace_image(grid, DenseDensity{grid}, largest(grid.values), camera, medium, options);
}

PathTracedImage path_trace_volume(const SparseGrid& grid, const CameraFrame& camera, const VolumeMedium& medium,
                                  const PathTraceOptions& options) {
  return trace_image(grid, SparseDensity{grid}, largest(grid.values), camera, medium, options);
}

}  // namespace pyro
