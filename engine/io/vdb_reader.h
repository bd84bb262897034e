#pragma once
// Reading OpenVDB files into plain data. vdb_reader.cpp is the only translation unit in the
// project that includes OpenVDB; everything here is plain C++ and glm, so the rest of the engine
// never pays for OpenVDB's headers.
//
// Coordinates: OpenVDB stores a value at every integer index coordinate (i, j, k), the voxel
// centre; its transform maps index space to world space. We keep that transform as a 4x4 affine
// matrix (column vectors: world = index_to_world * (i, j, k, 1); engine/volume/grid_header.h).
// Non-affine maps (frustum) are refused.
//
// A grid is read sparse (engine/volume/sparse_grid.h): the child process walks the tree's leaves
// and active tiles and writes bricks of 8^3 voxels into the shared result file, so memory grows
// with the active voxels; a dense copy (engine/volume/dense_grid.h) is made from it for the grids
// small enough to have one.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "engine/volume/dense_grid.h"
#include "engine/volume/sparse_grid.h"

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

// Lists every grid of the file (names, types, classes, transforms, counts, bounds) without
// reading voxel data. Throws UserError (file, "", why) for a missing, truncated or corrupt file.
std::vector<VdbGridInfo> list_vdb_grids(const std::string& path);

struct VdbGridChoice {
  std::string name;  // empty: "density" if there is such a float grid, else the first float grid
  int index = -1;    // >= 0: the grid at this position in the file (overrides name)
};

// Reads one float grid as a sparse fog volume: level sets become fog volumes (OpenVDB's
// sdfToFogVolume: 0 outside, rising to 1 inside across the narrow band), half floats are
// widened, leaves are copied whole (inactive voxels included) and active tiles voxel by voxel;
// inactive tiles are the background, 0. Throws UserError naming the file, the grid and what the
// file holds when the choice is not a float grid, when no float grid exists, when the transform
// is not affine, when the file is truncated or corrupt, when a value is not a finite density of
// magnitude at most 1e6 (naming the voxel), or when the active box has over 2^37 voxels. `note`
// (if given) receives a line saying which grid was chosen when it was not named explicitly;
// `stats` (if given) what the child process used.
struct VdbReadStats {
  uint64_t child_peak_rss_bytes = 0;  // the reading child's peak resident memory
};
SparseGrid read_vdb_grid_sparse(const std::string& path, const VdbGridChoice& choice = {},
                                std::string* note = nullptr, VdbReadStats* stats = nullptr);

// The largest box a grid may be made dense over (1 GiB of floats).
inline constexpr uint64_t kMaxDenseGridVoxels = uint64_t{1} << 28;

// The same grid made dense over its active bounding box (read_vdb_grid_sparse, then
// dense_from_sparse). Also refuses a grid whose box has over kMaxDenseGridVoxels voxels: those
// are read sparse.
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

// One grid of a file written by write_vdb_grids: dense values over origin..origin+dims-1 (x fastest;
// 3 floats a voxel for a vec3s grid), zeros skipped, with a per-axis voxel size and the world
// position of index (0, 0, 0).
struct VdbGridToWrite {
  std::string name;
  std::array<int, 3> origin{0, 0, 0}, dims{0, 0, 0};
  std::vector<float> values;
  bool vec3 = false;  // a vec3s grid (class "unknown"), else a float fog volume
  bool half_float = false;  // saved as 16-bit floats
  std::array<double, 3> voxel_size{1, 1, 1};
  std::array<double, 3> translation{0, 0, 0};
};

// Writes several grids into one OpenVDB file, in the order given (tests and generators: e.g. a
// fire's density, temperature and velocity). Written to a temporary name, then renamed.
void write_vdb_grids(const std::string& path, const std::vector<VdbGridToWrite>& grids);

}  // namespace pyro
