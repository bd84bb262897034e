#pragma once
// The bytes in which the VDB reader's child process (engine/io/isolated_call.h) hands its
// results to the engine: grid listings and dense grids, field by field in native byte order
// (both ends are the same executable). A dense grid's values are written in place into the
// shared result file (no copy in the child); decoding checks every length against what is left.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "engine/io/isolated_call.h"
#include "engine/io/vdb_reader.h"

namespace pyro {

void write_grid_infos(ResultWriter& out, const std::vector<VdbGridInfo>& grids);
std::vector<VdbGridInfo> decode_grid_infos(std::string_view bytes);

// A dense grid is written in three steps: begin_dense_grid with everything but the values,
// active count and maximum (grid.values is ignored) returns room for dims[0]·dims[1]·dims[2]
// floats to fill; end_dense_grid adds the count and the maximum.
float* begin_dense_grid(ResultWriter& out, const std::string& note, const DenseGrid& head);
void end_dense_grid(ResultWriter& out, uint64_t active_voxels, float max_value);
DenseGrid decode_dense_grid(std::string_view bytes, std::string* note);

}  // namespace pyro
