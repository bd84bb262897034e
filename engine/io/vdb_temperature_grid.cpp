#include "engine/io/vdb_temperature_grid.h"

#include "engine/core/user_error.h"
#include "engine/volume/grid_resample.h"

namespace pyro {

namespace {

const VdbGridInfo* find_grid(const std::vector<VdbGridInfo>& grids, const std::string& name) {
  for (const VdbGridInfo& g : grids)
    if (g.name == name) return &g;
  return nullptr;
}

}  // namespace

std::optional<VdbGridInfo> choose_temperature_grid(const std::string& path, const std::vector<VdbGridInfo>& grids,
                                                   const std::string& requested, const std::string& place) {
  if (requested == "none") return std::nullopt;
  if (requested.empty()) {
    for (const std::string& name : kTemperatureGridNames)
      if (const VdbGridInfo* g = find_grid(grids, name); g && g->is_float() && g->affine) return *g;
    return std::nullopt;
  }
  const VdbGridInfo* g = find_grid(grids, requested);
  if (!g)
    throw UserError(path, place,
                    "a temperature grid named \"" + requested + "\", found no grid of that name; the file holds " +
                        describe_grids(grids));
  if (!g->is_float() || !g->affine)
    throw UserError(path, place,
                    "a float temperature grid with an affine transform, found \"" + requested + "\" of type " +
                        g->value_type + "; the file holds " + describe_grids(grids));
  return *g;
}

DenseGrid read_temperature_grid(const std::string& path, const VdbGridInfo& grid, const GridHeader& density) {
  VdbGridChoice choice;
  choice.index = grid.index;
  return resample_into(read_vdb_grid(path, choice), density);
}

}  // namespace pyro
