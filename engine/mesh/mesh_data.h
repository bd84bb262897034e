#pragma once
// Triangle meshes on the CPU: positions and normals per vertex, three indices per triangle.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace pyro {

struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<uint32_t> indices;

  size_t triangle_count() const { return indices.size() / 3; }
  // Appends `other` moved by `offset` and scaled by `scale`.
  void append(const MeshData& other, const glm::vec3& offset = glm::vec3(0.0f), float scale = 1.0f);
};

// Every triangle winds counter-clockwise seen from the side its normals point to (outwards on
// the closed meshes: box, cylinder, cone), so back faces may be culled.

// A square in the y = 0 plane with half side `half_size`, normal +y.
MeshData make_ground_plane(float half_size);

// A box between corners lo and hi, with flat faces.
MeshData make_box(const glm::vec3& lo, const glm::vec3& hi);

// A box whose horizontal bottom face spans bottom_lo..bottom_hi in x and z at height bottom_lo.y,
// and top face top_lo..top_hi at top_lo.y: sheared or tapered, its faces flat where opposite
// sides stay parallel (a sheared box: a slanted leg).
MeshData make_slanted_box(const glm::vec3& bottom_lo, const glm::vec3& bottom_hi,
                          const glm::vec3& top_lo, const glm::vec3& top_hi);

// A capped cylinder about the y axis from y0 to y1 (smooth sides).
MeshData make_cylinder(float radius, float y0, float y1, int segments);

// A cone about the y axis with its base (radius) at y0 and apex at y1.
MeshData make_cone(float radius, float y0, float y1, int segments);

// A sphere of `radius` about `center` (smooth): `segments` around the y axis, `rings` from pole
// to pole.
MeshData make_sphere(float radius, const glm::vec3& center, int segments, int rings);

// The water tower of the paper's figures, standing on y = 0: four legs with cross braces, a
// central pipe, a cylindrical tank and a conical roof. Its bounds: x and z in [-1.05, 1.05]
// (the balcony and the roof's rim), y in [0, 6.6] (the finial's top).
MeshData make_water_tower();

}  // namespace pyro
