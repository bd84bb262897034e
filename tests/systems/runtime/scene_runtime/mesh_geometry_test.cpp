// Meshes in scenes: primitives at their documented sizes, and glTF / OBJ files written here read
// through a scene with their node transforms and the entry's placement (closed forms); damaged,
// missing and huge files refused with the scene, the entry and the file named.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/core/user_error.h"
#include "engine/mesh/mesh_file_check.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/load_scene_assets.h"
#include "systems/runtime/scene_runtime/mesh_geometry.h"
#include "systems/runtime/scene_runtime/resolve_scene.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

struct MeshBounds {
  glm::vec3 lo{1e30f}, hi{-1e30f};
};

MeshBounds bounds_of(const MeshData& m) {
  MeshBounds b;
  for (const glm::vec3& p : m.positions) {
    b.lo = glm::min(b.lo, p);
    b.hi = glm::max(b.hi, p);
  }
  return b;
}

void expect_near_vec3(const glm::vec3& got, const glm::vec3& want, const std::string& what) {
  EXPECT_NEAR(got.x, want.x, 1e-5f) << what;
  EXPECT_NEAR(got.y, want.y, 1e-5f) << what;
  EXPECT_NEAR(got.z, want.z, 1e-5f) << what;
}

MeshDescription primitive(const std::string& entry) {
  return parse_scene(R"({"meshes": [)" + entry + "]}", "primitives.json").meshes.at(0);
}

TEST(MeshPrimitives, StandOnTheirOriginAtTheirDocumentedSizes) {
  struct Case {
    std::string entry;
    glm::vec3 lo, hi;
  };
  const Case cases[] = {
      {R"({"type": "box", "size": [2, 3, 4]})", {-1, 0, -2}, {1, 3, 2}},
      {R"({"type": "box"})", {-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f}},
      {R"({"type": "sphere", "radius": 1.5})", {-1.5f, 0, -1.5f}, {1.5f, 3, 1.5f}},
      {R"({"type": "cylinder", "radius": 0.25, "height": 5})", {-0.25f, 0, -0.25f}, {0.25f, 5, 0.25f}},
      {R"({"type": "cone", "radius": 2, "height": 1})", {-2, 0, -2}, {2, 1, 2}},
      {R"({"type": "ground_plane"})", {-1, 0, -1}, {1, 0, 1}},
      {R"({"type": "water_tower"})", {-1.05f, 0, -1.05f}, {1.05f, 6.6f, 1.05f}}};
  for (const Case& c : cases) {
    const auto mesh = primitive_geometry(primitive(c.entry));
    ASSERT_TRUE(mesh) << c.entry;
    const MeshBounds b = bounds_of(mesh->data);
    expect_near_vec3(b.lo, c.lo, c.entry + " lower bound");
    expect_near_vec3(b.hi, c.hi, c.entry + " upper bound");
    // A closed primitive winds counter-clockwise outside: no triangle faces against its normals.
    if (!mesh->closed) continue;
    const MeshData& d = mesh->data;
    for (size_t t = 0; t < d.indices.size(); t += 3) {
      const uint32_t a = d.indices[t], bb = d.indices[t + 1], cc = d.indices[t + 2];
      const glm::vec3 face = glm::cross(d.positions[bb] - d.positions[a], d.positions[cc] - d.positions[a]);
      ASSERT_GE(glm::dot(face, d.normals[a] + d.normals[bb] + d.normals[cc]), -1e-6f) << c.entry << " triangle " << t / 3;
    }
  }
}

TEST(MeshPrimitives, KeysOfAnotherTypeAreRefused) {
  try {
    parse_scene(R"({"meshes": [{"type": "box", "radius": 1}]})", "keys.json");
    FAIL() << "radius on a box was accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.place(), "/meshes/0/radius");
    EXPECT_NE(std::string(e.what()).find("\"sphere\", \"cylinder\", \"cone\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_scene(R"({"meshes": [{"type": "file"}]})", "keys.json"), UserError);
  EXPECT_THROW(parse_scene(R"({"meshes": [{"type": "file", "file": "a.stl"}]})", "keys.json"), UserError);
}

void put_u32(std::string& s, uint32_t v) {
  for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

// A binary glTF of one triangle (0,0,0), (1,0,0), (0,1,0) without normals, placed by a parent
// node (translation 1, 2, 3) and a child (90 degrees about z, scale 2) that holds the mesh.
std::string triangle_glb() {
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
  std::string gltf = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"translation": [1, 2, 3], "children": [1]},
              {"rotation": [0, 0, 0.70710678, 0.70710678], "scale": [2, 2, 2], "mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [{"byteLength": 36}]})";
  while (gltf.size() % 4 != 0) gltf.push_back(' ');
  std::string glb = "glTF";
  put_u32(glb, 2);
  put_u32(glb, static_cast<uint32_t>(12 + 8 + gltf.size() + 8 + bin.size()));
  put_u32(glb, static_cast<uint32_t>(gltf.size()));
  glb += "JSON" + gltf;
  put_u32(glb, static_cast<uint32_t>(bin.size()));
  glb += std::string("BIN\0", 4) + bin;
  return glb;
}

// 10^8 triangles claimed by the accessors, in a few hundred bytes (its buffer does not exist).
constexpr const char* kHugeGltf = R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 1}, "indices": 0}]}],
  "accessors": [{"bufferView": 0, "componentType": 5125, "count": 300000000, "type": "SCALAR"},
                {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteLength": 1200000000}],
  "buffers": [{"uri": "huge.bin", "byteLength": 1200000000}]})";

void write_mesh_test_file(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

SceneAssets assets_of(const fs::path& scene) {
  return load_scene_assets(resolve_scene(load_scene(scene.string()), RuntimeOptions{}, 4096));
}

TEST(MeshFiles, GltfAndObjLoadWithTheirNodeTransformsAndPlacement) {
  const fs::path dir = test::scratch_dir("mesh_files");
  write_mesh_test_file(dir / "triangle.glb", triangle_glb());
  write_mesh_test_file(dir / "triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const fs::path scene = dir / "scene.json";
  write_mesh_test_file(scene, R"({"meshes": [
      {"type": "file", "file": "triangle.glb", "position": [10, 0, 0], "rotation_deg": [0, 90, 0], "scale": 0.5},
      {"type": "file", "file": "triangle.obj", "position": [0, 0, -5], "rotation_deg": [90, 90, 0], "scale": 3}]})");
  const SceneDescription d = load_scene(scene.string());
  const SceneAssets assets = assets_of(scene);
  ASSERT_EQ(assets.meshes.size(), 2u);
  // glTF: p -> (1, 2, 3) + Rz(90) 2 p; (x, y, z) -> (-y, x, z) about z. Flat normal: +z.
  const MeshData& glb = assets.meshes[0]->data;
  ASSERT_EQ(glb.positions.size(), 3u);
  const glm::vec3 in_file[3] = {{1, 2, 3}, {1, 4, 3}, {-1, 2, 3}};
  // Then the entry: 0.5 p, Ry(90): (x, y, z) -> (z, y, -x), + (10, 0, 0).
  const glm::vec3 in_world[3] = {{11.5f, 1, -0.5f}, {11.5f, 2, -0.5f}, {11.5f, 1, 0.5f}};
  const MeshPlacement glb_at{d.meshes[0].position, d.meshes[0].rotation_deg, d.meshes[0].scale};
  for (int k = 0; k < 3; ++k) {
    expect_near_vec3(glb.positions[k], in_file[k], "glTF vertex " + std::to_string(k));
    expect_near_vec3(glb.normals[k], {0, 0, 1}, "glTF flat normal");
    expect_near_vec3(glb_at.apply(glb.positions[k]), in_world[k], "placed glTF vertex " + std::to_string(k));
  }
  // OBJ: no nodes; the entry scales by 3, turns about x by 90 ((x, y, z) -> (x, -z, y)), then
  // about y by 90, then moves by (0, 0, -5).
  const MeshData& obj = assets.meshes[1]->data;
  ASSERT_EQ(obj.positions.size(), 3u);
  const glm::vec3 obj_world[3] = {{0, 0, -5}, {0, 0, -8}, {3, 0, -5}};
  const MeshPlacement obj_at{d.meshes[1].position, d.meshes[1].rotation_deg, d.meshes[1].scale};
  for (int k = 0; k < 3; ++k)
    expect_near_vec3(obj_at.apply(obj.positions[k]), obj_world[k], "placed OBJ vertex " + std::to_string(k));
}

// The refusal of mesh entry 0 of a scene naming `file`, written with `bytes` (none: absent).
std::string mesh_file_refusal(const std::string& file, const std::string* bytes) {
  const fs::path dir = test::scratch_dir("mesh_refusals");
  if (bytes) write_mesh_test_file(dir / file, *bytes);
  const fs::path scene = dir / "scene.json";
  write_mesh_test_file(scene, R"({"meshes": [{"type": "file", "file": ")" + file + R"("}]})");
  try {
    assets_of(scene);
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), scene.string());
    EXPECT_EQ(e.place(), "/meshes/0");
    EXPECT_NE(e.expected().find(file), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << file << " was accepted";
  return "";
}

TEST(MeshFiles, MissingTruncatedAndHugeFilesAreRefused) {
  EXPECT_NE(mesh_file_refusal("absent.glb", nullptr).find("no such file"), std::string::npos);
  const std::string glb = triangle_glb();
  const std::string cut = glb.substr(0, glb.size() - 10);
  EXPECT_NE(mesh_file_refusal("cut.glb", &cut).find("truncated"), std::string::npos);
  const std::string cut_json = std::string(kHugeGltf).substr(0, 100);
  EXPECT_NE(mesh_file_refusal("cut.gltf", &cut_json).find("not valid"), std::string::npos);
  const std::string huge = kHugeGltf;
  EXPECT_NE(mesh_file_refusal("huge.gltf", &huge).find("100000000 triangles, more than the limit of 20000000"),
            std::string::npos);
  const std::string obj_out_of_range = "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  EXPECT_NE(mesh_file_refusal("bad.obj", &obj_out_of_range).find("bad.obj"), std::string::npos);
}

}  // namespace
}  // namespace pyro
