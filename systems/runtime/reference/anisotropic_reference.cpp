#include "systems/runtime/reference/anisotropic_reference.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

#include "engine/math/anisotropic_optical_depth.h"
#include "engine/math/projected_ellipsoid.h"
#include "engine/math/shadow_ray_index.h"
#include "systems/runtime/reference/parallel_rows.h"
#include "systems/runtime/reference/pixel_ray.h"
#include "systems/runtime/reference/ray_pieces.h"

namespace pyro {

namespace {

// The pixels (inclusive ranges, one pixel of margin) a particle may cover.
struct PixelSpan {
  int x0, x1, y0, y1;
};

// Pixel centre (x + 0.5) sits at NDC 2 (x + 0.5) / W - 1, rows counted from the top.
bool pixel_span(const AnisotropicGaussian& g, const CameraFrame& camera, PixelSpan& span) {
  const ProjectedEllipsoid e = project_ellipsoid(g, glm::dmat4(camera.view_projection));
  if (e.cover == EllipsoidCover::hidden || !(g.extinction > 0.0f)) return false;
  const int w = camera.width, h = camera.height;
  span = {0, w - 1, 0, h - 1};
  if (e.cover == EllipsoidCover::full_screen) return true;
  const auto clamp_to = [](double v, int n) { return int(std::clamp(v, -1.0, double(n))); };
  span.x0 = clamp_to(std::floor((e.lo.x + 1.0) * 0.5 * w - 0.5) - 1.0, w);
  span.x1 = clamp_to(std::ceil((e.hi.x + 1.0) * 0.5 * w - 0.5) + 1.0, w);
  span.y0 = clamp_to(std::floor((1.0 - e.hi.y) * 0.5 * h - 0.5) - 1.0, h);
  span.y1 = clamp_to(std::ceil((1.0 - e.lo.y) * 0.5 * h - 0.5) + 1.0, h);
  return span.x0 <= span.x1 && span.y0 <= span.y1 && span.x1 >= 0 && span.y1 >= 0 && span.x0 < w &&
         span.y0 < h;
}

// The image with each part [a, b] of pixel ray w scattering its particles' colour times
// light(a, b, w), and emitting their emission (unlit).
template <class Light>
RgbImage render_particles(const std::vector<AnisotropicGaussian>& particles, const CameraFrame& camera,
                          const RgbImage& behind, const std::vector<float>& stop, int threads,
                          double max_piece_depth, Light&& light) {
  const std::size_t pixels = std::size_t(camera.width) * std::size_t(camera.height);
  if (behind.width != camera.width || behind.height != camera.height || stop.size() != pixels)
    throw std::invalid_argument("anisotropic reference: image sizes differ from the camera's");
  const glm::dvec3 eye(camera.eye);
  std::vector<std::size_t> visible;
  std::vector<PixelSpan> spans;
  std::vector<glm::dmat3> whitening;  // per visible particle: M, and u0 = M (eye - c)
  std::vector<glm::dvec3> eye_whitened;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    PixelSpan s;
    if (!pixel_span(particles[i], camera, s)) continue;
    visible.push_back(i);
    spans.push_back(s);
    whitening.push_back(whitening_matrix(particles[i]));
    eye_whitened.push_back(whitening.back() * (eye - glm::dvec3(particles[i].centre)));
  }
  RgbImage img = behind;
  parallel_rows(img.height, threads, [&](int y) {
    std::vector<std::size_t> row;  // indices into visible / spans
    for (std::size_t k = 0; k < visible.size(); ++k)
      if (spans[k].y0 <= y && y <= spans[k].y1) row.push_back(k);
    std::vector<AnisotropicRaySegment> segments;  // the pixel's hits, in the order added
    std::vector<std::size_t> owner;               // the particle of each
    RayPieces pieces;
    for (int x = 0; x < img.width; ++x) {
      const glm::dvec3 w = pixel_ray_direction(camera, x + 0.5, y + 0.5);
      const double t_stop = stop[std::size_t(y) * std::size_t(camera.width) + std::size_t(x)];
      pieces.clear();
      segments.clear();
      owner.clear();
      for (std::size_t k : row) {
        if (x < spans[k].x0 || x > spans[k].x1) continue;
        const std::size_t i = visible[k];
        const AnisotropicRaySegment s =
            anisotropic_ray_segment(whitening[k], eye_whitened[k], double(particles[i].extinction), w);
        const double a = std::max(s.t_enter, 0.0), b = std::min(s.t_exit, t_stop);
        if (!s.hit || b <= a) continue;
        pieces.add(a, b, s.t_closest, segments.size());
        segments.push_back(s);
        owner.push_back(i);
      }
      const glm::dvec3 L = pieces.integrate(
          [&](std::size_t i, double a, double b) { return segments[i].depth(a, b); },
          [&](std::size_t i) { return glm::dvec3(particles[owner[i]].color); },
          glm::dvec3(behind.at(x, y)[0], behind.at(x, y)[1], behind.at(x, y)[2]), max_piece_depth,
          [&](double a, double b) { return light(a, b, w); },
          [&](std::size_t i) { return glm::dvec3(particles[owner[i]].emission); });
      float* px = img.at(x, y);
      px[0] = float(L.x);
      px[1] = float(L.y);
      px[2] = float(L.z);
    }
  });
  return img;
}

// A uniform background, nothing opaque.
RgbImage uniform_image(const CameraFrame& camera, const glm::dvec3& colour) {
  RgbImage img;
  img.width = camera.width;
  img.height = camera.height;
  img.rgb.resize(std::size_t(3) * img.width * img.height);
  for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = float(colour[int(i % 3)]);
  return img;
}

std::vector<float> no_stop(const CameraFrame& camera) {
  return std::vector<float>(std::size_t(camera.width) * std::size_t(camera.height),
                            std::numeric_limits<float>::infinity());
}

}  // namespace

RgbImage render_anisotropic_reference(const std::vector<AnisotropicGaussian>& particles,
                                      const CameraFrame& camera, const glm::dvec3& background,
                                      int threads, double max_piece_depth) {
  return render_anisotropic_reference_over(particles, camera, uniform_image(camera, background), no_stop(camera),
                                           threads, max_piece_depth);
}

RgbImage render_anisotropic_reference_over(const std::vector<AnisotropicGaussian>& particles,
                                           const CameraFrame& camera, const RgbImage& behind,
                                           const std::vector<float>& stop, int threads, double max_piece_depth) {
  return render_particles(particles, camera, behind, stop, threads, max_piece_depth,
                          [](double, double, const glm::dvec3&) { return glm::dvec3(1.0); });
}

std::vector<ShadowCaster> anisotropic_casters(const std::vector<AnisotropicGaussian>& particles) {
  std::vector<ShadowCaster> casters;
  append_casters(particles, casters);
  return casters;
}

RgbImage render_lit_anisotropic_reference_over(const std::vector<AnisotropicGaussian>& particles,
                                               const CameraFrame& camera, const ReferenceSun& sun,
                                               const RgbImage& behind, const std::vector<float>& stop,
                                               int threads, double max_piece_depth) {
  const ShadowRayIndex index(anisotropic_casters(particles), sun.travel);
  const glm::dvec3 eye(camera.eye), travel = glm::normalize(sun.travel);
  return render_particles(particles, camera, behind, stop, threads, max_piece_depth,
                          [&](double a, double b, const glm::dvec3& w) {
                            const glm::dvec3 mid = eye + 0.5 * (a + b) * w;
                            const double tau = index.optical_depth_to_light(mid) + sun.mesh_depth_at(mid);
                            return sun.color * sun_scattering(sun.scattering, -glm::dot(travel, w), tau) +
                                   sun.ambient;
                          });
}

}  // namespace pyro
