#pragma once
// Reading OpenVDB files into plain data. vdb_reader.cpp is the only translation unit in the
// project that includes OpenVDB; everything here is plain C++ and glm, so the rest of the engine
// never pays for OpenVDB's headers.
//
// Coordinates: OpenVDB stores a value at every integer index coordinate (i, j, k), the voxel
// centre; its transform maps index space to world space. We keep that transform as a 4x4 affine
// matrix (column vectors: world = index_to_world * (i, j, k, 1)). Non-affine maps (frustum) are
// refused.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

namespace pyro {

struct VdbGridInfo {
  int index = 0;                 // position in the file, from 0
  std::string name;              // may repeat within a file
  std::string type;              // OpenVDB tree type, e.g. "Tree_float_5_4_3"
  std::string value_type;        // "float", "vec3s", "int32", "ptdataidx32", ...
  std::string grid_class;        // "fog volume", "level set", "staggered", "unknown"
  bool half_float = false;       // stored as 16-bit floats in the file
  std::array<double, 3> voxel_size{0, 0, 0};
  bool affine = true;            // the transform is affine (false: frustum or other)
  glm::dmat4 index_to_world{1.0};
  uint64_t active_voxels = 0;
  std::array<int, 3> bbox_min{0, 0, 0};  // active voxels' index bounding box (inclusive)
  std::array<int, 3> bbox_max{-1, -1, -1};
  bool is_float() const { return value_type == "float" || value_type == "double"; }
};

// A float grid made dense over its active bounding box. Inactive voxels hold the background of a
// fog volume (0). Element (x, y, z) holds index coordinate origin + (x, y, z).
struct DenseGrid {
  std::string file;
  std::string name;
  int file_index = 0;
  std::array<int, 3> origin{0, 0, 0};
  std::array<int, 3> dims{0, 0, 0};
  std::vector<float> values;  // x fastest: values[(z * dims[1] + y) * dims[0] + x]
  glm::dmat4 index_to_world{1.0};
  std::array<double, 3> voxel_size{1, 1, 1};
  uint64_t active_voxels = 0;
  float max_value = 0.0f;
  bool converted_from_level_set = false;
  bool half_float = false;

  bool empty() const { return values.empty(); }
  size_t size() const { return values.size(); }
  float at(int x, int y, int z) const {
    return values[(static_cast<size_t>(z) * dims[1] + y) * dims[0] + x];
  }
};

// Lists every grid of the file (names, types, classes, transforms, counts, bounds) without
// reading voxel data. Throws UserError (file, "", why) for a missing, truncated or corrupt file.
std::vector<VdbGridInfo> list_vdb_grids(const std::string& path);

struct VdbGridChoice {
  std::string name;  // empty: "density" if there is such a float grid, else the first float grid
  int index = -1;    // >= 0: the grid at this position in the file (overrides name)
};

// Reads one float grid as a dense fog volume: level sets become fog volumes (OpenVDB's
// sdfToFogVolume: 0 outside, rising to 1 inside across the narrow band), half floats are
// widened. Throws UserError naming the file, the grid and what the file holds when the choice
// is not a float grid, when no float grid exists, when the transform is not affine, or when the
// file is truncated or corrupt. `note` (if given) receives a line saying which grid was chosen
// when it was not named explicitly.
DenseGrid read_vdb_grid(const std::string& path, const VdbGridChoice& choice = {},
                        std::string* note = nullptr);

// A one-line description of every grid, for error messages: `"density" float fog volume
// (415642 voxels), "vel" vec3s unknown (1000000 voxels)`.
std::string describe_grids(const std::vector<VdbGridInfo>& grids);

// Writes a float fog volume (dense values over origin..origin+dims-1, zero skipped) as an
// OpenVDB file with the given uniform voxel size and world translation of index (0,0,0).
// Used by tools/make_sample_volume and by tests. Written to a temporary name, then renamed.
void write_vdb_fog_volume(const std::string& path, const std::string& grid_name,
                          const std::array<int, 3>& origin, const std::array<int, 3>& dims,
                          const std::vector<float>& values, double voxel_size,
                          const std::array<double, 3>& translation, bool half_float = false);

}  // namespace pyro
