#include "systems/reference/anisotropic_reference.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "engine/math/anisotropic_optical_depth.h"
#include "engine/math/projected_ellipsoid.h"
#include "systems/reference/parallel_rows.h"
#include "systems/reference/pixel_ray.h"
#include "systems/reference/ray_pieces.h"

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

}  // namespace

RgbImage render_anisotropic_reference(const std::vector<AnisotropicGaussian>& particles,
                                      const CameraFrame& camera, const glm::dvec3& background,
                                      int threads, double max_piece_depth) {
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
  RgbImage img;
  img.width = camera.width;
  img.height = camera.height;
  img.rgb.assign(std::size_t(3) * img.width * img.height, 0.0f);
  parallel_rows(img.height, threads, [&](int y) {
    std::vector<std::size_t> row;  // indices into visible / spans
    for (std::size_t k = 0; k < visible.size(); ++k)
      if (spans[k].y0 <= y && y <= spans[k].y1) row.push_back(k);
    std::vector<AnisotropicRaySegment> segments;  // the pixel's hits, in the order added
    std::vector<std::size_t> owner;               // the particle of each
    RayPieces pieces;
    for (int x = 0; x < img.width; ++x) {
      const glm::dvec3 w = pixel_ray_direction(camera, x + 0.5, y + 0.5);
      pieces.clear();
      segments.clear();
      owner.clear();
      for (std::size_t k : row) {
        if (x < spans[k].x0 || x > spans[k].x1) continue;
        const std::size_t i = visible[k];
        const AnisotropicRaySegment s =
            anisotropic_ray_segment(whitening[k], eye_whitened[k], double(particles[i].extinction), w);
        const double a = std::max(s.t_enter, 0.0), b = s.t_exit;
        if (!s.hit || b <= a) continue;
        pieces.add(a, b, s.t_closest, segments.size());
        segments.push_back(s);
        owner.push_back(i);
      }
      const glm::dvec3 L = pieces.integrate(
          [&](std::size_t i, double a, double b) { return segments[i].depth(a, b); },
          [&](std::size_t i) { return glm::dvec3(particles[owner[i]].color); }, background, max_piece_depth);
      float* px = img.at(x, y);
      px[0] = float(L.x);
      px[1] = float(L.y);
      px[2] = float(L.z);
    }
  });
  return img;
}

}  // namespace pyro
