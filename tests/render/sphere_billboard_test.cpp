// Spherical billboards (Umenhoffer et al. 2006): the rendered opacity against the closed form
// 1 - exp(-tau (1 - d/r) ds) along each pixel's exact ray; clipping by opaque geometry at the
// true intersection; and the artifacts they remove: planar billboards pop when the camera
// passes through a particle and when a particle sinks through a surface, spherical ones change
// smoothly (the largest frame-to-frame change is bounded).
#include <gtest/gtest.h>

#include <cmath>

#include "components/camera.h"
#include "components/frame_image.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

constexpr float kTau = 1.5f;
constexpr float kSphereBillboardRadius = 0.5f;

SceneDescription one_sphere(const glm::vec3& at, const glm::vec3& eye, const glm::vec3& target,
                            bool ground) {
  SceneDescription s;
  s.width = 96;
  s.height = 72;
  s.background = {0, 0, 0};
  s.camera.position = eye;
  s.camera.target = target;
  s.camera.up = std::abs(target.x - eye.x) + std::abs(target.z - eye.z) < 1e-6f ? glm::vec3(0, 0, -1)
                                                                              : glm::vec3(0, 1, 0);
  s.camera.fov_y_deg = 50.0f;
  s.camera.near = 0.05f;
  s.render.particles = ParticleShape::spherical;
  CloudDescription c;
  c.count = 1;
  c.radius = kSphereBillboardRadius;
  c.density = kTau;
  c.color = {1, 1, 1};
  c.box_min = c.box_max = at;
  s.clouds.push_back(c);
  if (ground) {
    MeshDescription g;
    g.kind = MeshKind::ground_plane;
    g.scale = 50.0f;
    g.color = {0, 0, 0};
    s.meshes.push_back(g);
  }
  return s;
}

std::vector<float> render_sphere_billboard(const SceneDescription& s, ParticleShape shape) {
  RuntimeOptions o;
  o.particles = shape;
  SceneRuntime r(s, o);
  r.step();
  return r.image().rgba;
}

TEST(SphereBillboard, OpacityFollowsTheExactChordOfEachRay) {
  const glm::vec3 at{0.4f, -0.2f, -2.5f};
  const SceneDescription s = one_sphere(at, {0, 0, 0}, {0, 0, -1}, false);
  const auto img = render_sphere_billboard(s, ParticleShape::spherical);
  const double t = std::tan(50.0 * M_PI / 360.0);
  double worst = 0;
  int covered = 0;
  for (int y = 0; y < 72; ++y)
    for (int x = 0; x < 96; ++x) {
      // The pixel centre's ray, in world space (camera at the origin looking down -z).
      const glm::dvec3 dir = glm::normalize(glm::dvec3((2.0 * (x + 0.5) / 96 - 1) * t * 96 / 72,
                                                       (1 - 2.0 * (y + 0.5) / 72) * t, -1.0));
      const glm::dvec3 c(at);
      const double along = glm::dot(c, dir);
      const double d = std::sqrt(std::max(glm::dot(c, c) - along * along, 0.0));
      double expected = 0;
      if (d < kSphereBillboardRadius) {
        const double chord = 2.0 * std::sqrt(kSphereBillboardRadius * kSphereBillboardRadius - d * d);
        expected = 1.0 - std::exp(-kTau * (1.0 - d / kSphereBillboardRadius) * chord);
        ++covered;
      }
      worst = std::max(worst, std::abs(img[(static_cast<size_t>(y) * 96 + x) * 4] - expected));
    }
  EXPECT_GT(covered, 200);
  EXPECT_LT(worst, 2e-3);  // half-float storage
}

TEST(SphereBillboard, OpaqueSurfaceCutsThePathWhereItReallyIs) {
  // Looking straight down at a sphere half sunk into the ground: the centre ray travels r inside
  // the medium before it hits the ground, so alpha = 1 - exp(-tau r).
  // Pixel (48, 36) is half a pixel off the axis in x and y; its ray is computed exactly.
  const auto img = render_sphere_billboard(one_sphere({0, 0, 0}, {0, 5, 0}, {0, 0, 0}, true), ParticleShape::spherical);
  const float centre = img[(static_cast<size_t>(36) * 96 + 48) * 4];
  const double t = std::tan(50.0 * M_PI / 360.0);
  // Camera at (0, 5, 0) looking down with up = -z: right = +x, image up = -z.
  const glm::dvec3 dir = glm::normalize(glm::dvec3((2.0 * 48.5 / 96 - 1) * t * 96 / 72, -1.0,
                                                   -(1 - 2.0 * 36.5 / 72) * t));
  const glm::dvec3 eye(0, 5, 0);
  const double closest = glm::dot(-eye, dir);  // ray parameter nearest the centre
  const double d = glm::length(eye + closest * dir);
  const double ground = 5.0 / -dir.y;           // ray parameter where it meets y = 0
  const double entry = closest - std::sqrt(kSphereBillboardRadius * kSphereBillboardRadius - d * d);
  const double expected = 1.0 - std::exp(-kTau * (1.0 - d / kSphereBillboardRadius) * (ground - entry));
  EXPECT_NEAR(centre, expected, 2e-3);
  EXPECT_LT(expected, 0.6) << "the ground must cut the path roughly in half";
}

double max_step(const std::vector<std::vector<float>>& frames) {
  double worst = 0;
  for (size_t k = 1; k < frames.size(); ++k)
    for (size_t i = 0; i < frames[k].size(); i += 4)
      worst = std::max(worst, static_cast<double>(std::abs(frames[k][i] - frames[k - 1][i])));
  return worst;
}

TEST(SphereBillboard, CameraPassingThroughAParticleDoesNotPop) {
  // The eye moves along the axis from in front of the particle through its centre and out of
  // the back, in steps of r/25. Planar: the billboard vanishes when its plane crosses the near plane. Spherical: the
  // path length inside the sphere shrinks continuously.
  std::vector<std::vector<float>> spherical, planar;
  for (int k = 0; k <= 50; ++k) {
    const float z = 0.6f - 0.02f * k;  // particle at the origin, eye from z = 0.6 to -0.4
    SceneDescription s = one_sphere({0, 0, 0}, {0, 0, z}, {0, 0, z - 1}, false);
    spherical.push_back(render_sphere_billboard(s, ParticleShape::spherical));
    planar.push_back(render_sphere_billboard(s, ParticleShape::planar));
  }
  EXPECT_LT(max_step(spherical), 0.08);
  EXPECT_GT(max_step(planar), 0.3);
}

TEST(SphereBillboard, ParticleSinkingThroughTheGroundDoesNotPop) {
  // Looking down at the ground; the particle sinks through it in steps of r/25. Planar: the
  // whole billboard (parallel to the ground) disappears at once. Spherical: smooth.
  std::vector<std::vector<float>> spherical, planar;
  for (int k = 0; k <= 50; ++k) {
    const float y = 0.5f - 0.02f * k;
    SceneDescription s = one_sphere({0, y, 0}, {0, 5, 0}, {0, 0, 0}, true);
    spherical.push_back(render_sphere_billboard(s, ParticleShape::spherical));
    planar.push_back(render_sphere_billboard(s, ParticleShape::planar));
  }
  EXPECT_LT(max_step(spherical), 0.08);
  EXPECT_GT(max_step(planar), 0.3);
}

}  // namespace
}  // namespace pyro
