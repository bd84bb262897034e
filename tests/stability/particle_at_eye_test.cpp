// Stability: a particle exactly at the eye. A viewpoint-facing billboard turns its normal to
// normalize(eye - centre); normalising the zero vector there would make every vertex of the
// billboard NaN. The engine keeps the viewplane axes at the eye
// (engine/math/billboard_alignment.h, content/shaders/billboard.vert); the GL image stays finite
// (BillboardAlignmentRender.ParticleAtTheEyeStaysFinite, tests/render) and so does the CPU
// ground truth, whose rays start inside the particle.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "engine/math/billboard_alignment.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/reference/particle_reference.h"

namespace pyro {
namespace {

TEST(StabilityParticleAtEye, ViewpointAxesAtTheEyeAreTheViewplaneAxes) {
  const glm::vec3 eye(1.0f, 2.0f, 3.0f), up(0, 1, 0), right(1, 0, 0);
  const BillboardAxes<float> axes = viewpoint_facing_axes(eye, eye, up, right);
  EXPECT_EQ(axes.right, right);
  EXPECT_EQ(axes.up, up);
  const BillboardAxes<double> daxes =
      viewpoint_facing_axes(glm::dvec3(eye), glm::dvec3(eye), glm::dvec3(up), glm::dvec3(right));
  EXPECT_EQ(daxes.right, glm::dvec3(right));
  EXPECT_EQ(daxes.up, glm::dvec3(up));
  // Just off the eye the construction is the ordinary one again (unit, orthogonal axes).
  const BillboardAxes<double> near_eye =
      viewpoint_facing_axes(glm::dvec3(eye) + glm::dvec3(1e-9, 0, -1e-9), glm::dvec3(eye),
                            glm::dvec3(up), glm::dvec3(right));
  EXPECT_NEAR(glm::length(near_eye.right), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(near_eye.right, near_eye.up), 0.0, 1e-12);
}

TEST(StabilityParticleAtEye, GroundTruthImageStaysFinite) {
  const glm::vec3 eye(0, 0, 5);
  ParticlePool pool(1);
  ParticleInit p;
  p.position = eye;
  p.radius = 1.0f;
  p.density = 0.8f;
  pool.spawn(p);
  const CameraFrame cam = make_camera_frame(eye, {0, 0, 0}, {0, 1, 0}, 45.0f, 0.1f, 100.0f, 16, 12);
  const RgbImage img = render_particles_reference(pool, cam, glm::dvec3(0.3), 1);
  for (float v : img.rgb) {
    ASSERT_TRUE(std::isfinite(v));
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 1.0f);
  }
}

}  // namespace
}  // namespace pyro
