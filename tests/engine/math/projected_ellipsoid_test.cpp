// The projected ellipsoid's rectangle (engine/math/projected_ellipsoid.h, Sigg et al. 2006)
// against the projections of many points of the ellipsoid's surface, and its classification of
// particles that hold the eye, cross the near plane or lie behind the eye.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "engine/core/rng.h"
#include "engine/math/camera_math.h"
#include "engine/math/projected_ellipsoid.h"
#include "tests/support/random_anisotropic.h"

namespace pyro {
namespace {

// NDC bounds of the projections of surface points c + R diag(3 s) x, |x| = 1, on a fine
// latitude-longitude grid (the true rectangle contains them and is at most a grid step wider).
void sampled_bounds(const AnisotropicGaussian& g, const glm::dmat4& vp, glm::dvec2& lo, glm::dvec2& hi) {
  const glm::dmat3 r = glm::mat3_cast(glm::normalize(glm::dquat(g.rotation)));
  lo = glm::dvec2(1e300);
  hi = glm::dvec2(-1e300);
  const int n = 400;
  for (int i = 0; i <= n; ++i) {
    const double th = 3.14159265358979 * i / n;
    for (int j = 0; j < 2 * n; ++j) {
      const double ph = 3.14159265358979 * j / n;
      const glm::dvec3 x(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      const glm::dvec3 p = glm::dvec3(g.centre) + r * (3.0 * glm::dvec3(g.scale) * x);
      const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
      const glm::dvec2 ndc(c.x / c.w, c.y / c.w);
      lo = glm::min(lo, ndc);
      hi = glm::max(hi, ndc);
    }
  }
}

TEST(ProjectedEllipsoid, RectangleIsTheTightBoundOfTheSurfacesImage) {
  Rng rng(17);
  const CameraFrame f = make_camera_frame({0.4f, 0.7f, 6.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f},
                                          50.0f, 0.5f, 50.0f, 320, 240);
  const glm::dmat4 vp(f.view_projection);
  for (int k = 0; k < 40; ++k) {
    const AnisotropicGaussian g = test::random_anisotropic(rng, 1.5f, 0.05f, 0.6f, 1.0f, 1.0f);
    const ProjectedEllipsoid e = project_ellipsoid(g, vp);
    ASSERT_EQ(e.cover, EllipsoidCover::rectangle) << "particle " << k;
    glm::dvec2 lo, hi;
    sampled_bounds(g, vp, lo, hi);
    // The grid's step is pi / 400: the sampled extreme lies within (1 - cos(step)) of the size;
    // a sample can touch the exact edge, so the containment allows rounding (1e-10).
    const double slack = 1e-4 * std::max(hi.x - lo.x, hi.y - lo.y);
    for (int a = 0; a < 2; ++a) {
      EXPECT_LE(e.lo[a], lo[a] + 1e-10) << k;
      EXPECT_GE(e.hi[a], hi[a] - 1e-10) << k;
      EXPECT_GT(e.lo[a], lo[a] - slack) << k;
      EXPECT_LT(e.hi[a], hi[a] + slack) << k;
    }
    const glm::dvec4 c = vp * glm::dvec4(glm::dvec3(g.centre), 1.0);
    EXPECT_NEAR(e.depth_ndc, c.z / c.w, 1e-12);
  }
}

TEST(ProjectedEllipsoid, EyeInsideNearPlaneCrossingAndBehindAreTold) {
  const CameraFrame f = make_camera_frame({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, {0.0f, 1.0f, 0.0f},
                                          60.0f, 0.2f, 50.0f, 64, 64);
  const glm::dmat4 vp(f.view_projection);
  AnisotropicGaussian g;
  g.scale = {0.5f, 0.1f, 0.1f};
  g.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
  g.centre = {0.0f, 0.05f, -0.1f};  // holds the eye
  EXPECT_EQ(project_ellipsoid(g, vp).cover, EllipsoidCover::full_screen);
  g.centre = {0.5f, 0.0f, -0.4f};  // in front of the eye, reaching through the near plane
  g.rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
  g.scale = {0.1f, 0.1f, 0.1f};
  ProjectedEllipsoid e = project_ellipsoid(g, vp);
  EXPECT_EQ(e.cover, EllipsoidCover::full_screen);
  EXPECT_GT(e.depth_ndc, -1.0);  // its centre lies beyond the near plane
  g.centre = {0.0f, 0.0f, -0.1f};  // wholly between the eye plane and the near plane
  g.scale = {0.02f, 0.02f, 0.02f};
  e = project_ellipsoid(g, vp);
  EXPECT_EQ(e.cover, EllipsoidCover::full_screen);
  EXPECT_EQ(e.depth_ndc, -1.0);
  g.centre = {0.0f, 0.0f, 2.0f};  // behind the eye
  EXPECT_EQ(project_ellipsoid(g, vp).cover, EllipsoidCover::hidden);
  g.centre = {0.0f, 0.0f, -2.0f};  // well in front
  EXPECT_EQ(project_ellipsoid(g, vp).cover, EllipsoidCover::rectangle);
}

}  // namespace
}  // namespace pyro
