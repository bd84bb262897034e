// The closed form of a mesh's shadow: a square plate (a thin box) above a white ground under a
// sun casts the convex hull of its two faces' projections along the sun onto the ground. Every
// ground pixel (albedo 1, read from the frame's half-float scene target) whose centre lies
// inside that footprint, farther than a margin (one pixel and two shadow-map texels) from its
// edge, shows the ambient light alone, and every pixel as far outside it shows the ambient light
// plus the sun's E cos(theta), both to 1e-3. The footprint's pixel count matches the hull's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "components/gpu_frame.h"
#include "components/view.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

constexpr int kSide = 128;                       // the frame, pixels
const glm::dvec3 kTravel(1.0, -2.0, 0.5);        // the sun's way
constexpr double kSun = 0.8, kAmbient = 0.1;     // E, A
constexpr double kPlateBottom = 2.0, kPlateTop = 2.1, kPlateHalf = 1.0;

std::string write_plate_scene(const std::filesystem::path& dir) {
  const std::string scene = (dir / "plate.json").string();
  std::ofstream(scene) << R"({
    "background": [0, 0, 0],
    "camera": {"position": [0.75, 12, 0.25], "target": [0.75, 0, 0.25], "up": [0, 0, -1], "fov_y_deg": 30, "near": 1, "far": 20},
    "lights": [{"type": "directional", "direction": [1, -2, 0.5], "color": [1, 1, 1], "intensity": 0.8},
               {"type": "ambient", "color": [0.1, 0.1, 0.1]}],
    "shadows": {"method": "map"},
    "meshes": [{"type": "ground_plane", "scale": 20, "color": [1, 1, 1]},
               {"type": "box", "size": [2, 0.1, 2], "position": [0, 2, 0], "color": [1, 1, 1]}]
  })";
  return scene;
}

// The plate's shadow on y = 0: the convex hull (counter-clockwise, Andrew's monotone chain) of
// its eight corners moved along the sun to the ground, in (x, z).
std::vector<glm::dvec2> footprint() {
  std::vector<glm::dvec2> p;
  for (double y : {kPlateBottom, kPlateTop})
    for (double x : {-kPlateHalf, kPlateHalf})
      for (double z : {-kPlateHalf, kPlateHalf}) {
        const double t = y / -kTravel.y;
        p.push_back({x + t * kTravel.x, z + t * kTravel.z});
      }
  std::sort(p.begin(), p.end(), [](auto a, auto b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const auto cross = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<glm::dvec2> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const size_t start = hull.size();
    for (const glm::dvec2& q : p) {
      while (hull.size() >= start + 2 && cross(hull[hull.size() - 2], hull.back(), q) <= 0) hull.pop_back();
      hull.push_back(q);
    }
    hull.pop_back();
    std::reverse(p.begin(), p.end());
  }
  return hull;
}

// Positive outside the convex polygon, negative inside: the largest signed distance to its edges'
// lines (inside: minus the distance to the boundary; outside: at most the distance).
double signed_distance(const std::vector<glm::dvec2>& hull, glm::dvec2 q) {
  double d = -1e300;
  for (size_t i = 0; i < hull.size(); ++i) {
    const glm::dvec2 a = hull[i], b = hull[(i + 1) % hull.size()];
    const glm::dvec2 n = glm::normalize(glm::dvec2(b.y - a.y, a.x - b.x));  // outward for counter-clockwise
    d = std::max(d, glm::dot(q - a, n));
  }
  return d;
}

// Whether the ray o + t r (t in [0, 1]) passes through the plate (slab intersection).
bool hits_plate(const glm::dvec3& o, const glm::dvec3& r) {
  const glm::dvec3 lo(-kPlateHalf, kPlateBottom, -kPlateHalf), hi(kPlateHalf, kPlateTop, kPlateHalf);
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 3; ++k) {
    if (r[k] == 0.0) {
      if (o[k] < lo[k] || o[k] > hi[k]) return false;
      continue;
    }
    double a = (lo[k] - o[k]) / r[k], b = (hi[k] - o[k]) / r[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a), t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

TEST(MeshShadow, APlateDarkensExactlyItsProjectedFootprint) {
  const std::filesystem::path dir = test::scratch_dir("mesh_shadow");
  RuntimeOptions o;
  o.readback = true;
  o.width_override = kSide;
  o.height_override = kSide;
  SceneRuntime runtime(load_scene(write_plate_scene(dir)), o);
  runtime.draw_frame(0);
  const std::vector<float> rgba = runtime.world().resource<GpuFrame>().eyes.at(0).scene->read_rgba();
  const glm::dmat4 unproject = glm::inverse(glm::dmat4(runtime.world().resource<View>().eyes.at(0).view_projection));
  const std::vector<glm::dvec2> hull = footprint();
  const double lit = kAmbient + kSun * -kTravel.y / glm::length(kTravel);
  // One pixel's diagonal on the ground, and two texels of the shadow map (1024 across the plate's
  // extent across the light, stretched onto the ground by the light's slant).
  const double pixel = 2.0 * 12.0 * std::tan(glm::radians(15.0)) / kSide, texel = 2.4 / 1022.0 / 0.87;
  const double margin = std::sqrt(2.0) * pixel + 2.0 * texel;
  int dark = 0, bright = 0, dark_pixels = 0, hull_pixels = 0, wrong = 0, seen = 0;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const glm::dvec4 ndc((x + 0.5) / kSide * 2.0 - 1.0, (y + 0.5) / kSide * 2.0 - 1.0, -1.0, 1.0);
      glm::dvec4 near = unproject * ndc, far = unproject * glm::dvec4(ndc.x, ndc.y, 1.0, 1.0);
      near /= near.w, far /= far.w;
      const glm::dvec3 a(near), b(far);
      const glm::dvec3 g = a + (b - a) * (a.y / (a.y - b.y));  // where the pixel's ray meets y = 0
      if (hits_plate(a, b - a)) continue;                        // the plate hides the ground there
      const double d = signed_distance(hull, {g.x, g.z});
      const double value = rgba[4 * (size_t(kSide - 1 - y) * kSide + size_t(x))];  // row 0 at the top
      ++seen;
      hull_pixels += d < 0.0;
      dark_pixels += value < 0.5 * (kAmbient + lit);
      if (std::abs(d) <= margin) continue;
      const double expected = d < 0.0 ? kAmbient : lit;
      (d < 0.0 ? dark : bright) += 1;
      if (std::abs(value - expected) > 1e-3 * expected) ++wrong;
      EXPECT_NEAR(value, expected, 1e-3 * expected) << "pixel " << x << ", " << y << " at " << d << " from the edge";
      ASSERT_LE(wrong, 5);
    }
  std::printf("footprint: %d of %d ground pixels dark (the hull holds %d); %d inside and %d outside its margin "
              "of %.4f\n", dark_pixels, seen, hull_pixels, dark, bright, margin);
  EXPECT_GT(dark, 500);
  EXPECT_GT(bright, 5000);
  EXPECT_NEAR(dark_pixels, hull_pixels, 0.01 * hull_pixels);
}

}  // namespace
}  // namespace pyro
