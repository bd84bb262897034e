#pragma once
// The bytes in which the VDB reader's child process (engine/io/isolated_call.h) hands its
// results to the engine: grid listings and sparse grids, field by field in native byte order
// (both ends are the same executable). A sparse grid's bricks are written in place into the
// shared result file (no copy in the child); decoding checks every length against what is left
// and every entry of the brick table against the bricks there are.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "engine/io/isolated_call.h"
#include "engine/io/vdb_reader.h"
#include "engine/volume/sparse_grid.h"

namespace pyro {

void write_grid_infos(ResultWriter& out, const std::vector<VdbGridInfo>& grids);
std::vector<VdbGridInfo> decode_grid_infos(std::string_view bytes);

// A sparse grid is written in two steps: begin_sparse_grid with its header and its brick table
// (SparseGrid::slots, empty for an empty box; `bricks` stored ones) returns room for the bricks'
// values to fill, zeroed; end_sparse_grid adds the active count and the maximum.
float* begin_sparse_grid(ResultWriter& out, const std::string& note, const GridHeader& head,
                         const std::vector<int32_t>& slots, uint64_t bricks);
void end_sparse_grid(ResultWriter& out, uint64_t active_voxels, float max_value);
SparseGrid decode_sparse_grid(std::string_view bytes, std::string* note);

}  // namespace pyro
