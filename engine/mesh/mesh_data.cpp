#include "engine/mesh/mesh_data.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace pyro {

void MeshData::append(const MeshData& other, const glm::vec3& offset, float scale) {
  const auto base = static_cast<uint32_t>(positions.size());
  for (const glm::vec3& p : other.positions) positions.push_back(p * scale + offset);
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  for (uint32_t i : other.indices) indices.push_back(base + i);
}

namespace {

void add_quad(MeshData& m, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
              const glm::vec3& d) {
  // a b c d counter-clockwise seen from the side the normal points to.
  const glm::vec3 n = glm::normalize(glm::cross(b - a, d - a));
  const auto base = static_cast<uint32_t>(m.positions.size());
  for (const glm::vec3& p : {a, b, c, d}) {
    m.positions.push_back(p);
    m.normals.push_back(n);
  }
  for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

}  // namespace

MeshData make_ground_plane(float h) {
  MeshData m;
  add_quad(m, {-h, 0, h}, {h, 0, h}, {h, 0, -h}, {-h, 0, -h});
  return m;
}

MeshData make_box(const glm::vec3& lo, const glm::vec3& hi) {
  return make_slanted_box({lo.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, hi.y, lo.z},
                          {hi.x, hi.y, hi.z});
}

MeshData make_slanted_box(const glm::vec3& bottom_lo, const glm::vec3& bottom_hi,
                          const glm::vec3& top_lo, const glm::vec3& top_hi) {
  MeshData m;
  const glm::vec3 p000{bottom_lo.x, bottom_lo.y, bottom_lo.z}, p100{bottom_hi.x, bottom_lo.y, bottom_lo.z},
      p001{bottom_lo.x, bottom_lo.y, bottom_hi.z}, p101{bottom_hi.x, bottom_lo.y, bottom_hi.z},
      p010{top_lo.x, top_lo.y, top_lo.z}, p110{top_hi.x, top_lo.y, top_lo.z},
      p011{top_lo.x, top_lo.y, top_hi.z}, p111{top_hi.x, top_lo.y, top_hi.z};
  add_quad(m, p001, p101, p111, p011);  // +z
  add_quad(m, p100, p000, p010, p110);  // -z
  add_quad(m, p101, p100, p110, p111);  // +x
  add_quad(m, p000, p001, p011, p010);  // -x
  add_quad(m, p011, p111, p110, p010);  // +y
  add_quad(m, p000, p100, p101, p001);  // -y
  return m;
}

MeshData make_cylinder(float r, float y0, float y1, int segments) {
  MeshData m;
  const float step = 2.0f * std::numbers::pi_v<float> / segments;
  for (int s = 0; s < segments; ++s) {
    const float a0 = s * step, a1 = (s + 1) * step;
    const glm::vec3 n0{std::cos(a0), 0, -std::sin(a0)}, n1{std::cos(a1), 0, -std::sin(a1)};
    const auto base = static_cast<uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {n0 * r + glm::vec3(0, y0, 0), n1 * r + glm::vec3(0, y0, 0),
                                           n1 * r + glm::vec3(0, y1, 0), n0 * r + glm::vec3(0, y1, 0)});
    m.normals.insert(m.normals.end(), {n0, n1, n1, n0});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
    // caps
    for (int cap = 0; cap < 2; ++cap) {
      const float y = cap ? y1 : y0;
      const glm::vec3 n{0, cap ? 1.0f : -1.0f, 0};
      const auto b = static_cast<uint32_t>(m.positions.size());
      m.positions.insert(m.positions.end(), {glm::vec3(0, y, 0), n0 * r + glm::vec3(0, y, 0),
                                             n1 * r + glm::vec3(0, y, 0)});
      m.normals.insert(m.normals.end(), {n, n, n});
      if (cap) m.indices.insert(m.indices.end(), {b, b + 1, b + 2});
      else m.indices.insert(m.indices.end(), {b, b + 2, b + 1});
    }
  }
  return m;
}

MeshData make_cone(float r, float y0, float y1, int segments) {
  MeshData m;
  const float step = 2.0f * std::numbers::pi_v<float> / segments;
  const float slope = r / (y1 - y0);
  for (int s = 0; s < segments; ++s) {
    const float a0 = s * step, a1 = (s + 1) * step, am = (s + 0.5f) * step;
    const glm::vec3 d0{std::cos(a0), 0, -std::sin(a0)}, d1{std::cos(a1), 0, -std::sin(a1)},
        dm{std::cos(am), 0, -std::sin(am)};
    auto normal = [&](const glm::vec3& d) { return glm::normalize(glm::vec3(d.x, slope, d.z)); };
    const auto base = static_cast<uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {d0 * r + glm::vec3(0, y0, 0), d1 * r + glm::vec3(0, y0, 0),
                                           glm::vec3(0, y1, 0)});
    m.normals.insert(m.normals.end(), {normal(d0), normal(d1), normal(dm)});
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
    const auto b = static_cast<uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {glm::vec3(0, y0, 0), d0 * r + glm::vec3(0, y0, 0),
                                           d1 * r + glm::vec3(0, y0, 0)});
    m.normals.insert(m.normals.end(), 3, glm::vec3(0, -1, 0));
    m.indices.insert(m.indices.end(), {b, b + 2, b + 1});
  }
  return m;
}

MeshData make_sphere(float r, const glm::vec3& center, int segments, int rings) {
  MeshData m;
  const float pi = std::numbers::pi_v<float>;
  for (int i = 0; i <= rings; ++i) {  // ring 0 at the top pole
    const float theta = pi * static_cast<float>(i) / static_cast<float>(rings);
    for (int j = 0; j <= segments; ++j) {
      const float phi = 2.0f * pi * static_cast<float>(j) / static_cast<float>(segments);
      const glm::vec3 d{std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)};
      m.positions.push_back(center + r * d);
      m.normals.push_back(d);
    }
  }
  const auto row = static_cast<uint32_t>(segments + 1);
  for (uint32_t i = 0; i < static_cast<uint32_t>(rings); ++i) {
    for (uint32_t j = 0; j < static_cast<uint32_t>(segments); ++j) {
      // Counter-clockwise seen from outside, as the cylinder's sides: lower ring, then upper.
      const uint32_t lo = (i + 1) * row + j, up = i * row + j;
      if (i + 1 < static_cast<uint32_t>(rings)) m.indices.insert(m.indices.end(), {lo, lo + 1, up + 1});
      if (i > 0) m.indices.insert(m.indices.end(), {lo, up + 1, up});
    }
  }
  return m;
}

MeshData make_water_tower() {
  MeshData m;
  const float leg = 0.09f, foot = 0.95f, head = 0.7f, top = 4.0f;
  // Four slanted legs, a slanted box each (12 triangles: the vertex and setup work of a small
  // mesh dominates its cost on llvmpipe).
  for (int sx : {-1, 1}) {
    for (int sz : {-1, 1}) {
      const glm::vec3 b{sx * foot, 0.0f, sz * foot}, t{sx * head, top, sz * head};
      m.append(make_slanted_box(b - glm::vec3(leg, 0, leg), b + glm::vec3(leg, 0, leg),
                                t - glm::vec3(leg, 0, leg), t + glm::vec3(leg, 0, leg)));
    }
  }
  // Horizontal braces between the legs at two heights.
  for (float y : {1.4f, 2.8f}) {
    const float o = foot + (head - foot) * y / top;
    const float t = 0.045f;
    m.append(make_box({-o, y - t, -o - t}, {o, y + t, -o + t}));
    m.append(make_box({-o, y - t, o - t}, {o, y + t, o + t}));
    m.append(make_box({-o - t, y - t, -o}, {-o + t, y + t, o}));
    m.append(make_box({o - t, y - t, -o}, {o + t, y + t, o}));
  }
  m.append(make_cylinder(0.16f, 0.0f, top, 16));           // riser pipe
  m.append(make_cylinder(1.05f, top - 0.1f, top + 0.05f, 40));  // balcony floor
  m.append(make_cylinder(0.95f, top, top + 1.5f, 40));      // tank
  m.append(make_cone(1.05f, top + 1.5f, top + 2.3f, 40));   // roof
  m.append(make_cylinder(0.05f, top + 2.3f, top + 2.6f, 8)); // finial
  return m;
}

}  // namespace pyro
