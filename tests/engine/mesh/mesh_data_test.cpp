// The procedural meshes' winding (engine/mesh/mesh_data.h): the opaque pass culls the back faces
// of closed meshes, which changes nothing only if every triangle winds counter-clockwise seen
// from outside and the mesh has no holes. Checked per triangle against its vertex normals and,
// for the convex pieces, against the direction away from the centre; closedness by every edge
// being walked once each way.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>

#include "engine/mesh/mesh_data.h"

namespace pyro {
namespace {

glm::vec3 face_normal(const MeshData& m, size_t t) {
  const glm::vec3& a = m.positions[m.indices[3 * t]];
  const glm::vec3& b = m.positions[m.indices[3 * t + 1]];
  const glm::vec3& c = m.positions[m.indices[3 * t + 2]];
  return glm::cross(b - a, c - a);
}

// Triangles whose winding disagrees with any of their vertex normals.
size_t misoriented(const MeshData& m) {
  size_t bad = 0;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const glm::vec3 n = face_normal(m, t);
    for (int k = 0; k < 3; ++k) bad += glm::dot(n, m.normals[m.indices[3 * t + k]]) <= 0.0f;
  }
  return bad;
}

// Triangles of a convex mesh facing its centre (the mean of its vertices).
size_t facing_inwards(const MeshData& m) {
  glm::vec3 centre(0.0f);
  for (const glm::vec3& p : m.positions) centre += p;
  centre /= static_cast<float>(m.positions.size());
  size_t bad = 0;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const glm::vec3 mid = (m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] +
                           m.positions[m.indices[3 * t + 2]]) / 3.0f;
    bad += glm::dot(face_normal(m, t), mid - centre) <= 0.0f;
  }
  return bad;
}

// Directed edges (between positions, vertices being repeated per face) not matched by the same
// edge walked the other way: 0 for a closed, consistently wound mesh.
size_t unmatched_edges(const MeshData& m) {
  using Key = std::tuple<long, long, long>;
  auto key = [](const glm::vec3& p) {
    return Key{std::lround(p.x * 1e4f), std::lround(p.y * 1e4f), std::lround(p.z * 1e4f)};
  };
  std::map<std::pair<Key, Key>, int> balance;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Key a = key(m.positions[m.indices[3 * t + k]]);
      const Key b = key(m.positions[m.indices[3 * t + (k + 1) % 3]]);
      if (a < b) ++balance[{a, b}];
      else --balance[{b, a}];
    }
  }
  size_t open = 0;
  for (const auto& [edge, n] : balance) open += static_cast<size_t>(std::abs(n));
  return open;
}

TEST(MeshData, ConvexPiecesAreClosedAndWoundOutwards) {
  const MeshData pieces[] = {
      make_box({-1.0f, 0.0f, -0.5f}, {2.0f, 1.0f, 0.5f}),
      make_slanted_box({0.9f, 0.0f, 0.9f}, {1.1f, 0.0f, 1.1f}, {0.6f, 4.0f, 0.6f}, {0.8f, 4.0f, 0.8f}),
      make_cylinder(0.95f, 4.0f, 5.5f, 40),
      make_cone(1.05f, 5.5f, 6.3f, 40),
  };
  for (const MeshData& m : pieces) {
    ASSERT_GT(m.triangle_count(), 0u);
    EXPECT_EQ(misoriented(m), 0u);
    EXPECT_EQ(facing_inwards(m), 0u);
    EXPECT_EQ(unmatched_edges(m), 0u);
  }
}

TEST(MeshData, WaterTowerIsClosedAndWoundOutwards) {
  const MeshData tower = make_water_tower();
  EXPECT_EQ(misoriented(tower), 0u);
  EXPECT_EQ(unmatched_edges(tower), 0u);
}

TEST(MeshData, TheChecksSeeAFlippedTriangleAndAHole) {
  MeshData box = make_box({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f});
  std::swap(box.indices[1], box.indices[2]);  // one triangle wound the other way
  EXPECT_GT(misoriented(box), 0u);
  EXPECT_GT(facing_inwards(box), 0u);
  EXPECT_GT(unmatched_edges(box), 0u);
  MeshData open = make_box({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f});
  open.indices.resize(open.indices.size() - 3);  // a face's triangle missing
  EXPECT_GT(unmatched_edges(open), 0u);
}

}  // namespace
}  // namespace pyro
