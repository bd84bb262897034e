#include "engine/mesh/mesh_file_check.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"

namespace pyro {

namespace {

using json = nlohmann::json;

bool ends_with_lower(std::string s, std::string_view suffix) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

[[noreturn]] void refuse(const std::string& path, const std::string& what) { throw UserError(path, "", what); }

void check_limit(const std::string& path, uint64_t triangles) {
  if (triangles > kMaxMeshFileTriangles)
    refuse(path, "the file holds " + std::to_string(triangles) + " triangles, more than the limit of " +
                     std::to_string(kMaxMeshFileTriangles) + " for one mesh file; it was not read");
}

uint32_t little_endian_u32(const unsigned char* b) {
  return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}

// A .glb: the 12-byte header (magic "glTF", version 2, total length) and the first chunk, which
// must be the JSON (glTF 2.0 specification, section 4.4 "GLB File Format Specification").
json glb_json(const std::string& path, std::ifstream& in) {
  const uint64_t size = std::filesystem::file_size(path);
  unsigned char header[20];
  if (!in.read(reinterpret_cast<char*>(header), sizeof header))
    refuse(path, "a .glb file is at least 20 bytes long (header and JSON chunk header); this one is " +
                     std::to_string(size) + " bytes: truncated?");
  if (std::memcmp(header, "glTF", 4) != 0) refuse(path, "not a binary glTF file: it does not start with \"glTF\"");
  if (little_endian_u32(header + 4) != 2)
    refuse(path, "expected binary glTF version 2, found version " + std::to_string(little_endian_u32(header + 4)));
  const uint32_t declared = little_endian_u32(header + 8);
  if (declared != size)
    refuse(path, "the .glb header says the file is " + std::to_string(declared) + " bytes long, but it is " +
                     std::to_string(size) + " bytes: truncated or damaged");
  const uint32_t json_length = little_endian_u32(header + 12);
  if (std::memcmp(header + 16, "JSON", 4) != 0) refuse(path, "the first chunk of a .glb file must be its JSON");
  if (uint64_t(json_length) + 20 > size)
    refuse(path, "the JSON chunk runs past the end of the file: truncated or damaged");
  std::string text(json_length, '\0');
  in.read(text.data(), json_length);
  return json::parse(text);
}

uint64_t accessor_count(const json& gltf, const json& index) {
  if (!index.is_number_unsigned()) throw std::runtime_error("an accessor index is not a whole number");
  const json& accessors = gltf.at("accessors");
  const uint64_t i = index.get<uint64_t>();
  if (i >= accessors.size()) throw std::runtime_error("an accessor index is out of range");
  return accessors.at(i).at("count").get<uint64_t>();
}

// Triangles of one primitive by its mode: 4 triangles, 5 strip, 6 fan; points and lines none.
uint64_t primitive_triangles(const json& gltf, const json& primitive) {
  const int mode = primitive.value("mode", 4);
  const uint64_t n = primitive.contains("indices") ? accessor_count(gltf, primitive.at("indices"))
                                                   : accessor_count(gltf, primitive.at("attributes").at("POSITION"));
  if (mode == 4) return n / 3;
  if (mode == 5 || mode == 6) return n >= 2 ? n - 2 : 0;
  return 0;
}

// a + b, a * b, held at the largest count instead of wrapping around (a file may claim any count).
uint64_t saturating_add(uint64_t a, uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }
uint64_t saturating_mul(uint64_t a, uint64_t b) { return b != 0 && a > UINT64_MAX / b ? UINT64_MAX : a * b; }

// Each mesh's triangles times the nodes that place it (at least once).
uint64_t gltf_triangles(const json& gltf) {
  const json empty = json::array();
  const json& meshes = gltf.contains("meshes") ? gltf.at("meshes") : empty;
  std::vector<uint64_t> uses(meshes.size(), 0);
  if (gltf.contains("nodes"))
    for (const json& node : gltf.at("nodes"))
      if (node.contains("mesh") && node.at("mesh").is_number_unsigned() && node.at("mesh").get<uint64_t>() < uses.size())
        ++uses[node.at("mesh").get<uint64_t>()];
  uint64_t total = 0;
  for (size_t m = 0; m < meshes.size(); ++m) {
    uint64_t per_mesh = 0;
    for (const json& p : meshes[m].at("primitives")) per_mesh = saturating_add(per_mesh, primitive_triangles(gltf, p));
    total = saturating_add(total, saturating_mul(per_mesh, std::max<uint64_t>(uses[m], 1)));
  }
  return total;
}

uint64_t check_gltf(const std::string& path, std::ifstream& in, bool binary) {
  json gltf;
  try {
    if (binary) {
      gltf = glb_json(path, in);
    } else {
      std::stringstream text;
      text << in.rdbuf();
      gltf = json::parse(text.str());
    }
  } catch (const json::exception& e) {
    refuse(path, std::string("the glTF JSON is not valid (truncated or damaged?): ") + e.what());
  }
  uint64_t triangles = 0;
  try {
    triangles = gltf_triangles(gltf);
  } catch (const std::exception& e) {
    refuse(path, std::string("the glTF meshes or accessors are malformed: ") + e.what());
  }
  check_limit(path, triangles);
  return triangles;
}

// Faces "f a b c ..." of n corners make n - 2 triangles; the scan stops past the limit.
uint64_t check_obj(const std::string& path, std::ifstream& in) {
  uint64_t triangles = 0;
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 2 || line[0] != 'f' || (line[1] != ' ' && line[1] != '\t')) continue;
    std::istringstream corners(line.substr(2));
    std::string corner;
    uint64_t n = 0;
    while (corners >> corner) ++n;
    if (n >= 3) triangles += n - 2;
    if (triangles > kMaxMeshFileTriangles) check_limit(path, triangles);
  }
  return triangles;
}

}  // namespace

std::optional<MeshFileFormat> mesh_file_format(const std::string& path) {
  if (ends_with_lower(path, ".gltf")) return MeshFileFormat::gltf;
  if (ends_with_lower(path, ".glb")) return MeshFileFormat::glb;
  if (ends_with_lower(path, ".obj")) return MeshFileFormat::obj;
  return std::nullopt;
}

uint64_t check_mesh_file(const std::string& path) {
  const std::optional<MeshFileFormat> format = mesh_file_format(path);
  if (!format) refuse(path, "expected a mesh file ending in \".gltf\", \".glb\" or \".obj\"");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) refuse(path, "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(path, "cannot open the file for reading");
  if (*format == MeshFileFormat::obj) return check_obj(path, in);
  return check_gltf(path, in, *format == MeshFileFormat::glb);
}

}  // namespace pyro
