// The only translation unit that includes OpenVDB (see vdb_reader.h). Learned from OpenVDB's
// own vdb_print and vdb_render (openvdb/cmd/), written afresh.
#include "engine/io/vdb_reader.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
#include <openvdb/tools/LevelSetUtil.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include <unistd.h>

#include "engine/core/user_error.h"
#include "engine/io/isolated_call.h"
#include "engine/io/vdb_file_check.h"
#include "engine/io/vdb_grid_transfer.h"

namespace pyro {

namespace {

// Dense grids larger than this are refused rather than allocated (1 GiB of floats).
constexpr uint64_t kMaxDenseVoxels = uint64_t{1} << 28;

void initialize_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

std::string grid_class_name(openvdb::GridClass c) {
  switch (c) {
    case openvdb::GRID_LEVEL_SET: return "level set";
    case openvdb::GRID_FOG_VOLUME: return "fog volume";
    case openvdb::GRID_STAGGERED: return "staggered";
    default: return "unknown";
  }
}

// OpenVDB's Mat4 multiplies row vectors (p' = p M, translation in row 3); glm multiplies column
// vectors, so element (row r, column c) of OpenVDB's matrix is glm's m[r][c] (column r, row c).
glm::dmat4 to_glm(const openvdb::math::Mat4d& m) {
  glm::dmat4 out(1.0);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[r][c] = m(r, c);
  return out;
}

// Cheap checks before OpenVDB sees the file: it exists, is a regular file and starts with the
// magic number 0x56444220 (" BDV" read as a little-endian int64's low bytes).
void check_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw UserError(path, "", "cannot open VDB file: " +
                                  std::string(std::filesystem::exists(path, ec)
                                                  ? "not a regular file"
                                                  : "No such file or directory"));
  std::ifstream in(path, std::ios::binary);
  unsigned char magic[8] = {};
  if (!in.read(reinterpret_cast<char*>(magic), 8))
    throw UserError(path, "", "not an OpenVDB file: shorter than its 8-byte header");
  const unsigned char expected[8] = {0x20, 0x42, 0x44, 0x56, 0, 0, 0, 0};
  if (std::memcmp(magic, expected, 8) != 0)
    throw UserError(path, "", "not an OpenVDB file: the magic number 0x56444220 is missing");
}

VdbGridInfo info_of(const openvdb::GridBase& g, int index) {
  VdbGridInfo info;
  info.index = index;
  info.name = g.getName();
  info.type = g.type();
  info.value_type = g.valueType();
  info.grid_class = grid_class_name(g.getGridClass());
  info.half_float = g.saveFloatAsHalf();
  const openvdb::Vec3d vs = g.voxelSize();
  info.voxel_size = {vs[0], vs[1], vs[2]};
  const auto map = g.transform().baseMap();
  info.affine = map->isLinear();
  if (info.affine) info.index_to_world = to_glm(map->getAffineMap()->getMat4());
  // The file's statistics metadata (written by OpenVDB since 2.0): voxel count and bounds,
  // without reading the tree.
  if (auto count = g.getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_VOXEL_COUNT))
    info.active_voxels = static_cast<uint64_t>(count->value());
  auto bmin = g.getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
  auto bmax = g.getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
  if (bmin && bmax && info.active_voxels > 0) {
    for (int a = 0; a < 3; ++a) {
      info.bbox_min[a] = bmin->value()[a];
      info.bbox_max[a] = bmax->value()[a];
    }
  }
  return info;
}

// Runs f, turning everything OpenVDB or the standard library can throw into a UserError: a
// truncated or corrupt file is the user's to fix, not a crash.
template <class F>
auto guarded(const std::string& path, const std::string& place, F&& f) {
  try {
    return f();
  } catch (const UserError&) {
    throw;
  } catch (const openvdb::Exception& e) {
    throw UserError(path, place, std::string("cannot read OpenVDB file (truncated or corrupt?): ") + e.what());
  } catch (const std::bad_alloc&) {
    throw UserError(path, place, "cannot read OpenVDB file (truncated or corrupt?): it asks for more memory than there is");
  } catch (const std::exception& e) {
    throw UserError(path, place, std::string("cannot read OpenVDB file (truncated or corrupt?): ") + e.what());
  }
}

std::string quote(const std::string& s) { return "\"" + s + "\""; }

// Writes the grid made dense over its active bounding box into the child's result (`head`
// holds the fields known before: file, name, transform, ...).
template <class GridT>
void densify_into(const GridT& grid, DenseGrid head, const std::string& note, ResultWriter& out) {
  const openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
  const uint64_t active = grid.activeVoxelCount();
  if (active == 0 || box.empty()) {
    head.dims = {0, 0, 0};
    begin_dense_grid(out, note, head);
    end_dense_grid(out, active, 0.0f);
    return;
  }
  const openvdb::Coord dim = box.dim();
  const uint64_t n = uint64_t(dim[0]) * uint64_t(dim[1]) * uint64_t(dim[2]);
  if (n > kMaxDenseVoxels)
    throw UserError("", quote(grid.getName()),
                    "a grid whose active bounding box has at most 2^28 voxels, found " +
                        std::to_string(n));
  for (int a = 0; a < 3; ++a) {
    head.origin[a] = box.min()[a];
    head.dims[a] = dim[a];
  }
  float* values = begin_dense_grid(out, note, head);  // zero-filled: a fresh file region
  // OpenVDB's dense copy walks the tree leaf by leaf (tiles included) on TBB's threads; the
  // layout with x fastest matches DenseGrid's index (z * ny + y) * nx + x.
  using Dense = openvdb::tools::Dense<float, openvdb::tools::LayoutXYZ>;
  Dense dense(box, values);
  openvdb::tools::copyToDense(grid, dense, /*serial=*/false);
  float mx = 0.0f;
  for (uint64_t i = 0; i < n; ++i) mx = std::max(mx, values[i]);
  end_dense_grid(out, active, mx);
}

// Densities beyond this magnitude come from damaged bytes, not from a simulation.
constexpr double kMaxDensity = 1e6;

// Refuses what the importer and the renderer cannot take in: a non-finite or absurd density (the
// grid and the voxel named) or a degenerate transform.
void check_grid_values(const std::string& path, const DenseGrid& g) {
  const std::string grid = quote(g.name);
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(g.voxel_size[a]) || !(g.voxel_size[a] > 1e-9 && g.voxel_size[a] < 1e9))
      throw UserError(path, "grid " + grid, "a voxel size in (1e-9, 1e9) on every axis, found " +
                                                std::to_string(g.voxel_size[a]));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(g.index_to_world[c][r]))
        throw UserError(path, "grid " + grid, "a finite index-to-world transform");
  size_t i = 0;
  for (int z = 0; z < g.dims[2]; ++z)
    for (int y = 0; y < g.dims[1]; ++y)
      for (int x = 0; x < g.dims[0]; ++x, ++i) {
        const float v = g.values[i];
        if (std::isfinite(v) && std::fabs(v) <= kMaxDensity) continue;
        char found[64];
        std::snprintf(found, sizeof found, "%g", static_cast<double>(v));
        throw UserError(path,
                        "grid " + grid + ", voxel (" + std::to_string(g.origin[0] + x) + ", " +
                            std::to_string(g.origin[1] + y) + ", " + std::to_string(g.origin[2] + z) + ")",
                        "a finite density of magnitude at most 1e6, found " + std::string(found));
      }
}

}  // namespace

std::string describe_grids(const std::vector<VdbGridInfo>& grids) {
  if (grids.empty()) return "no grids";
  std::string s;
  for (const VdbGridInfo& g : grids) {
    if (!s.empty()) s += ", ";
    s += "[" + std::to_string(g.index) + "] " + quote(g.name) + " " + g.value_type + " " +
         g.grid_class + " (" + std::to_string(g.active_voxels) + " voxels)";
  }
  return s;
}

namespace {

// The readers proper. They run only inside the child process of run_isolated (see
// isolated_call.h for why); the public functions below fork it and decode what it returns.
std::vector<VdbGridInfo> list_grids_in_this_process(const std::string& path) {
  initialize_openvdb();
  return guarded(path, "", [&] {
    openvdb::io::File file(path);
    file.open(false);
    openvdb::GridPtrVecPtr metas = file.readAllGridMetadata();
    std::vector<VdbGridInfo> out;
    for (size_t i = 0; i < metas->size(); ++i) out.push_back(info_of(*(*metas)[i], int(i)));
    file.close();
    return out;
  });
}

void read_grid_in_this_process(const std::string& path, const VdbGridChoice& choice,
                               ResultWriter& out) {
  std::string note_text;
  std::string* note = &note_text;
  const std::vector<VdbGridInfo> grids = list_grids_in_this_process(path);
  const std::string holds = "the file holds " + describe_grids(grids);
  int pick = -1;
  if (choice.index >= 0) {
    if (choice.index >= int(grids.size()))
      throw UserError(path, "grid index " + std::to_string(choice.index),
                      "a grid index in [0, " + std::to_string(grids.size()) + "); " + holds);
    pick = choice.index;
  } else if (!choice.name.empty()) {
    for (const VdbGridInfo& g : grids)
      if (g.name == choice.name) {
        pick = g.index;
        break;
      }
    if (pick < 0) throw UserError(path, "grid " + quote(choice.name), "no grid of that name; " + holds);
  } else {
    for (const VdbGridInfo& g : grids)
      if (g.name == "density" && g.is_float()) {
        pick = g.index;
        break;
      }
    if (pick < 0) {
      for (const VdbGridInfo& g : grids)
        if (g.is_float()) {
          pick = g.index;
          break;
        }
      if (pick < 0)
        throw UserError(path, "", "a float grid (fog volume or level set) to import, found none; " + holds);
      if (note) *note = "no float grid named \"density\"; using the first float grid, " + quote(grids[pick].name);
    } else if (note) {
      *note = "using grid [" + std::to_string(pick) + "] \"density\"";
    }
  }
  const VdbGridInfo& info = grids[pick];
  const std::string place = "grid [" + std::to_string(pick) + "] " + quote(info.name);
  if (!info.is_float())
    throw UserError(path, place,
                    "a float grid (fog volume or level set), found a " + info.value_type +
                        " grid (vector, integer and point grids cannot be imported); " + holds);
  if (!info.affine)
    throw UserError(path, place, "a grid with an affine transform, found a non-linear (frustum) map");

  // Grids are read by position: names may repeat (OpenVDB tells repeats apart as "name[n]").
  int repeat = 0;
  for (int i = 0; i < pick; ++i) repeat += grids[i].name == info.name;
  const std::string unique = repeat == 0 ? info.name : info.name + "[" + std::to_string(repeat) + "]";

  DenseGrid head;
  head.file = path;
  head.name = info.name;
  head.file_index = pick;
  head.index_to_world = info.index_to_world;
  head.voxel_size = info.voxel_size;
  head.half_float = info.half_float;
  guarded(path, place, [&] {
    openvdb::io::File file(path);
    file.open(false);
    openvdb::GridBase::Ptr base = file.readGrid(unique);
    file.close();
    head.converted_from_level_set = base->getGridClass() == openvdb::GRID_LEVEL_SET;
    if (auto fg = openvdb::GridBase::grid<openvdb::FloatGrid>(base)) {
      if (head.converted_from_level_set) openvdb::tools::sdfToFogVolume(*fg);
      densify_into(*fg, head, note_text, out);
    } else if (auto dg = openvdb::GridBase::grid<openvdb::DoubleGrid>(base)) {
      if (head.converted_from_level_set) openvdb::tools::sdfToFogVolume(*dg);
      densify_into(*dg, head, note_text, out);
    } else {
      throw UserError(path, place, "a float grid, found tree type " + base->type());
    }
    return 0;
  });
}

void write_fog_volume_in_this_process(const std::string& path, const std::string& grid_name,
                                      const std::array<int, 3>& origin,
                                      const std::array<int, 3>& dims,
                                      const std::vector<float>& values, double voxel_size,
                                      const std::array<double, 3>& translation, bool half_float) {
  initialize_openvdb();
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
  auto acc = grid->getAccessor();
  size_t k = 0;
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x, ++k)
        if (values[k] != 0.0f)
          acc.setValue(openvdb::Coord(origin[0] + x, origin[1] + y, origin[2] + z), values[k]);
  openvdb::math::Transform::Ptr xf = openvdb::math::Transform::createLinearTransform(voxel_size);
  xf->postTranslate(openvdb::Vec3d(translation[0], translation[1], translation[2]));
  grid->setTransform(xf);
  grid->setName(grid_name);
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  grid->setSaveFloatAsHalf(half_float);
  const std::string tmp = path + ".tmp";
  {
    openvdb::io::File file(tmp);
    file.write({grid});
    file.close();
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
}

}  // namespace

// The child's limits for this file: unless set, 2.5 GiB (the largest dense grid, 1 GiB, twice,
// and room for OpenVDB) plus 64 bytes a byte of file (its trees decompressed), at most half the
// machine's memory (run_isolated's default, applied when this is larger).
static IsolationLimits limits_for(const std::string& path) {
  IsolationLimits limits = vdb_isolation_limits();
  if (limits.memory_bytes == 0) {
    std::error_code ec;
    const uint64_t bytes = std::filesystem::file_size(path, ec);
    const uint64_t want = (uint64_t{5} << 29) + 64 * (ec ? 0 : bytes);
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    const uint64_t half = pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) / 2 : want;
    limits.memory_bytes = std::min(want, half);
  }
  return limits;
}

std::vector<VdbGridInfo> list_vdb_grids(const std::string& path) {
  check_file(path);
  check_vdb_file_structure(path);
  std::vector<VdbGridInfo> grids;
  run_isolated(
      path, "reading the OpenVDB file's grid list",
      [&](ResultWriter& out) { write_grid_infos(out, list_grids_in_this_process(path)); },
      [&](std::string_view bytes) { grids = decode_grid_infos(bytes); }, limits_for(path));
  return grids;
}

DenseGrid read_vdb_grid(const std::string& path, const VdbGridChoice& choice, std::string* note) {
  check_file(path);
  check_vdb_file_structure(path);
  // The child's result: the note's length and text, then the grid.
  DenseGrid grid;
  run_isolated(
      path, "reading the OpenVDB file",
      [&](ResultWriter& out) { read_grid_in_this_process(path, choice, out); },
      [&](std::string_view bytes) {
        std::string child_note;
        grid = decode_dense_grid(bytes, &child_note);
        if (note && !child_note.empty()) *note = child_note;
      },
      limits_for(path));
  check_grid_values(path, grid);
  return grid;
}

void write_vdb_fog_volume(const std::string& path, const std::string& grid_name,
                          const std::array<int, 3>& origin, const std::array<int, 3>& dims,
                          const std::vector<float>& values, double voxel_size,
                          const std::array<double, 3>& translation, bool half_float) {
  // Also in a child: the parent process never starts OpenVDB or its TBB threads (isolated_call.h).
  run_isolated(
      path, "writing the OpenVDB file",
      [&](ResultWriter&) {
        write_fog_volume_in_this_process(path, grid_name, origin, dims, values, voxel_size,
                                         translation, half_float);
      },
      [](std::string_view) {}, vdb_isolation_limits());
}

}  // namespace pyro
