// The only translation unit that includes OpenVDB (see vdb_reader.h). Learned from OpenVDB's
// own vdb_print and vdb_render (openvdb/cmd/), written afresh.
#include "engine/io/vdb_reader.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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
#include "engine/volume/sparse_grid.h"

namespace pyro {

namespace {

constexpr int kSide = SparseGrid::kBrickSide;

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

// Which bricks of the box hold a value, as the table SparseGrid::slots: marked per brick, then
// given slots in the table's order.
class BrickTable {
 public:
  explicit BrickTable(const GridHeader& head) : origin_(head.origin), bd_(brick_dims_for(head.dims)) {
    slots.assign(box_bricks(bd_), -1);
  }
  // Marks the bricks meeting the index box [lo, hi] (inclusive, inside the grid's box).
  void mark(const openvdb::Coord& lo, const openvdb::Coord& hi) {
    int b0[3], b1[3];
    for (int a = 0; a < 3; ++a) {
      b0[a] = (lo[a] - origin_[a]) / kSide;
      b1[a] = (hi[a] - origin_[a]) / kSide;
    }
    for (int z = b0[2]; z <= b1[2]; ++z)
      for (int y = b0[1]; y <= b1[1]; ++y)
        for (int x = b0[0]; x <= b1[0]; ++x) slots[at(x, y, z)] = 0;
  }
  // Gives the marked bricks their slots; returns how many there are.
  uint64_t assign() {
    int32_t next = 0;
    for (int32_t& s : slots) s = s < 0 ? -1 : next++;
    return uint64_t(next);
  }
  // For c in the same leaf as lo (both inside the box): which of the 2 x 2 x 2 bricks from lo's
  // it is in, as bit (dz * 2 + dy) * 2 + dx.
  int brick_bit(const openvdb::Coord& lo, const openvdb::Coord& c) const {
    int bit = 0;
    for (int a = 2; a >= 0; --a) bit = bit * 2 + ((c[a] - origin_[a]) / kSide - (lo[a] - origin_[a]) / kSide);
    return bit;
  }
  // Where index coordinate c's value goes among the bricks (c inside the box), or null when
  // its brick is not stored (all its values are 0).
  float* voxel(float* bricks, const openvdb::Coord& c) const {
    const int x = c[0] - origin_[0], y = c[1] - origin_[1], z = c[2] - origin_[2];
    const int32_t slot = slots[at(x / kSide, y / kSide, z / kSide)];
    if (slot < 0) return nullptr;
    return bricks + size_t(slot) * SparseGrid::kBrickVoxels + size_t(SparseGrid::in_brick(x, y, z));
  }
  std::vector<int32_t> slots;

 private:
  size_t at(int bx, int by, int bz) const { return (size_t(bz) * bd_[1] + size_t(by)) * bd_[0] + size_t(bx); }
  std::array<int, 3> origin_, bd_;
};

// A box clipped to another; false when they do not meet.
bool clip(const openvdb::CoordBBox& box, const openvdb::CoordBBox& to, openvdb::Coord& lo, openvdb::Coord& hi) {
  lo = openvdb::Coord::maxComponent(box.min(), to.min());
  hi = openvdb::Coord::minComponent(box.max(), to.max());
  return lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2];
}

// What holds the grid's values: its leaves, and its active tiles with their boxes. Tiles that are
// not active are the fog volume's background: 0, which absent voxels hold already.
template <class GridT>
struct GridPieces {
  using LeafT = typename GridT::TreeType::LeafNodeType;
  std::vector<const LeafT*> leaves;
  std::vector<std::pair<openvdb::CoordBBox, float>> tiles;

  explicit GridPieces(const GridT& grid) {
    for (auto it = grid.tree().cbeginLeaf(); it; ++it) leaves.push_back(&*it);
    auto tile = grid.cbeginValueOn();
    tile.setMaxDepth(tile.getLeafDepth() - 1);  // tiles only, no leaf voxels
    for (; tile; ++tile) {
      openvdb::CoordBBox b;
      if (!tile.isTileValue() || !tile.getBoundingBox(b)) continue;
      tiles.emplace_back(b, static_cast<float>(*tile));
    }
  }
  // Marks the bricks that will hold a value (bits not all 0): those of each leaf found on
  // TBB's threads (a leaf meets at most 2 x 2 x 2 bricks), then marked in order.
  void mark(const openvdb::CoordBBox& box, BrickTable& table) const {
    std::vector<uint8_t> meets(leaves.size(), 0);  // bit (dz * 2 + dy) * 2 + dx: brick first + d
    tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.size()), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i < r.end(); ++i) meets[i] = bricks_with_values(*leaves[i], box, table);
    });
    openvdb::Coord lo, hi;
    for (size_t i = 0; i < leaves.size(); ++i) {
      if (!meets[i] || !clip(leaves[i]->getNodeBoundingBox(), box, lo, hi)) continue;
      for (int bit = 0; bit < 8; ++bit)
        if (meets[i] >> bit & 1) {
          const openvdb::Coord c = lo.offsetBy(kSide * (bit & 1), kSide * (bit >> 1 & 1), kSide * (bit >> 2));
          table.mark(c, c);  // c: in that brick, maybe past the box
        }
    }
    for (const auto& [b, v] : tiles)
      if (v != 0.0f && clip(b, box, lo, hi)) table.mark(lo, hi);
  }
  // Which of the bricks that leaf meets inside the box get a value whose bits are not all 0.
  static uint8_t bricks_with_values(const LeafT& leaf, const openvdb::CoordBBox& box, const BrickTable& table) {
    openvdb::Coord lo, hi;
    if (!clip(leaf.getNodeBoundingBox(), box, lo, hi)) return 0;
    uint8_t meets = 0;
    for (openvdb::Coord c = lo; c[2] <= hi[2]; ++c[2])
      for (c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
        for (c[0] = lo[0]; c[0] <= hi[0]; ++c[0]) {
          const float v = static_cast<float>(leaf.getValue(c));
          uint32_t bits;
          std::memcpy(&bits, &v, sizeof bits);
          if (bits != 0) meets |= uint8_t(1u << table.brick_bit(lo, c));
        }
    return meets;
  }
  // Copies every leaf's values inside the box (all of them, active or not, as a dense copy
  // would), the leaves spread over threads, then every active tile's value over its voxels.
  void copy(const openvdb::CoordBBox& box, const BrickTable& table, float* values) const {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.size()), [&](const tbb::blocked_range<size_t>& r) {
      openvdb::Coord lo, hi;
      for (size_t i = r.begin(); i < r.end(); ++i) {
        const LeafT& leaf = *leaves[i];
        if (!clip(leaf.getNodeBoundingBox(), box, lo, hi)) continue;
        for (openvdb::Coord c = lo; c[2] <= hi[2]; ++c[2])
          for (c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
            for (c[0] = lo[0]; c[0] <= hi[0]; ++c[0])
              if (float* to = table.voxel(values, c)) *to = static_cast<float>(leaf.getValue(c));
      }
    });
    openvdb::Coord lo, hi;
    for (const auto& [b, v] : tiles) {
      if (v == 0.0f || !clip(b, box, lo, hi)) continue;
      for (openvdb::Coord c = lo; c[2] <= hi[2]; ++c[2])
        for (c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
          for (c[0] = lo[0]; c[0] <= hi[0]; ++c[0]) *table.voxel(values, c) = v;
    }
  }
};

// Densities beyond this magnitude come from damaged bytes, not from a simulation.
constexpr double kMaxDensity = 1e6;

// The largest value of the bricks (at least 0) and the first voxel, in the dense order (z, then
// y, then x), whose value is not a finite density of magnitude at most 1e6 (none: -1).
struct ValueScan {
  float max = 0.0f;
  int64_t first_bad = -1;
  float bad_value = 0.0f;
};

ValueScan scan_values(const GridHeader& head, const std::vector<int32_t>& slots, const float* values) {
  const std::array<int, 3> bd = brick_dims_for(head.dims);
  ValueScan total;
  std::mutex join;
  tbb::parallel_for(tbb::blocked_range<int>(0, bd[2]), [&](const tbb::blocked_range<int>& r) {
    ValueScan part;
    for (int bz = r.begin(); bz < r.end(); ++bz)
      for (int by = 0; by < bd[1]; ++by)
        for (int bx = 0; bx < bd[0]; ++bx) {
          const int32_t slot = slots[(size_t(bz) * bd[1] + size_t(by)) * bd[0] + size_t(bx)];
          if (slot < 0) continue;
          const float* brick = values + size_t(slot) * SparseGrid::kBrickVoxels;
          for (int i = 0; i < SparseGrid::kBrickVoxels; ++i) {
            const float v = brick[i];
            part.max = std::max(part.max, v);
            if (std::isfinite(v) && std::fabs(v) <= kMaxDensity) continue;
            const int64_t x = bx * kSide + (i & 7), y = by * kSide + ((i >> 3) & 7), z = bz * kSide + (i >> 6);
            const int64_t key = (z * head.dims[1] + y) * head.dims[0] + x;
            if (part.first_bad < 0 || key < part.first_bad) {
              part.first_bad = key;
              part.bad_value = v;
            }
          }
        }
    const std::lock_guard<std::mutex> lock(join);
    total.max = std::max(total.max, part.max);
    if (part.first_bad >= 0 && (total.first_bad < 0 || part.first_bad < total.first_bad)) {
      total.first_bad = part.first_bad;
      total.bad_value = part.bad_value;
    }
  });
  return total;
}

// Refuses a value the importer and the renderer cannot take in, naming the grid and the voxel.
void check_values(const std::string& path, const GridHeader& head, const ValueScan& scan) {
  if (scan.first_bad < 0) return;
  const int64_t nx = head.dims[0], ny = head.dims[1];
  const int64_t x = scan.first_bad % nx, y = (scan.first_bad / nx) % ny, z = scan.first_bad / (nx * ny);
  char found[64];
  std::snprintf(found, sizeof found, "%g", static_cast<double>(scan.bad_value));
  throw UserError(path,
                  "grid " + quote(head.name) + ", voxel (" + std::to_string(head.origin[0] + x) + ", " +
                      std::to_string(head.origin[1] + y) + ", " + std::to_string(head.origin[2] + z) + ")",
                  "a finite density of magnitude at most 1e6, found " + std::string(found));
}

// Writes the grid into the child's result as bricks of its active bounding box (`head` holds
// the fields known before: file, name, transform, ...), leaf by leaf and tile by tile: no dense
// copy, memory in proportion to the active voxels.
template <class GridT>
void sparsify_into(const GridT& grid, GridHeader head, const std::string& path, const std::string& note,
                   ResultWriter& out) {
  const openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
  const uint64_t active = grid.activeVoxelCount();
  if (active == 0 || box.empty()) {
    head.dims = {0, 0, 0};
    begin_sparse_grid(out, note, head, {}, 0);
    end_sparse_grid(out, active, 0.0f);
    return;
  }
  // The box's sides in 64 bits (OpenVDB's dim() overflows for boxes spanning the index range).
  int64_t side[3];
  double bricks_in_box = 1.0;
  bool long_side = false;
  for (int a = 0; a < 3; ++a) {
    side[a] = int64_t(box.max()[a]) - int64_t(box.min()[a]) + 1;
    bricks_in_box *= double((side[a] + kSide - 1) / kSide);
    long_side = long_side || side[a] > (int64_t{1} << 30);
  }
  if (bricks_in_box > double(SparseGrid::kMaxBoxBricks) || long_side)
    throw UserError("", quote(grid.getName()),
                    "a grid whose active bounding box has at most 2^37 voxels (2^28 bricks of 8^3) and "
                    "sides of at most 2^30, found " +
                        std::to_string(side[0]) + " x " + std::to_string(side[1]) + " x " + std::to_string(side[2]));
  for (int a = 0; a < 3; ++a) {
    head.origin[a] = box.min()[a];
    head.dims[a] = int(side[a]);
  }
  BrickTable table(head);
  const GridPieces<GridT> pieces(grid);
  pieces.mark(box, table);
  const uint64_t bricks = table.assign();
  float* values = begin_sparse_grid(out, note, head, table.slots, bricks);  // zeroed
  pieces.copy(box, table, values);
  const ValueScan scan = scan_values(head, table.slots, values);
  check_values(path, head, scan);
  end_sparse_grid(out, active, scan.max);
}

// Refuses what the importer and the renderer cannot take in (the values are checked in the
// child, as they are copied): a degenerate transform.
void check_grid_header(const std::string& path, const GridHeader& g) {
  const std::string grid = quote(g.name);
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(g.voxel_size[a]) || !(g.voxel_size[a] > 1e-9 && g.voxel_size[a] < 1e9))
      throw UserError(path, "grid " + grid, "a voxel size in (1e-9, 1e9) on every axis, found " +
                                                std::to_string(g.voxel_size[a]));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(g.index_to_world[c][r]))
        throw UserError(path, "grid " + grid, "a finite index-to-world transform");
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

  GridHeader head;
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
      sparsify_into(*fg, head, path, note_text, out);
    } else if (auto dg = openvdb::GridBase::grid<openvdb::DoubleGrid>(base)) {
      if (head.converted_from_level_set) openvdb::tools::sdfToFogVolume(*dg);
      sparsify_into(*dg, head, path, note_text, out);
    } else {
      throw UserError(path, place, "a float grid, found tree type " + base->type());
    }
    return 0;
  });
}

openvdb::math::Transform::Ptr transform_of(const VdbGridToWrite& g) {
  openvdb::math::Transform::Ptr xf = openvdb::math::Transform::createLinearTransform(1.0);
  xf->preScale(openvdb::Vec3d(g.voxel_size[0], g.voxel_size[1], g.voxel_size[2]));
  xf->postTranslate(openvdb::Vec3d(g.translation[0], g.translation[1], g.translation[2]));
  return xf;
}

template <class GridType, int Components>
openvdb::GridBase::Ptr dense_to_grid(const VdbGridToWrite& g) {
  typename GridType::Ptr grid = GridType::create();
  auto acc = grid->getAccessor();
  size_t k = 0;
  for (int z = 0; z < g.dims[2]; ++z)
    for (int y = 0; y < g.dims[1]; ++y)
      for (int x = 0; x < g.dims[0]; ++x, ++k) {
        const float* v = &g.values[Components * k];
        const openvdb::Coord at(g.origin[0] + x, g.origin[1] + y, g.origin[2] + z);
        if constexpr (Components == 1) {
          if (v[0] != 0.0f) acc.setValue(at, v[0]);
        } else if (v[0] != 0.0f || v[1] != 0.0f || v[2] != 0.0f) {
          acc.setValue(at, openvdb::Vec3s(v[0], v[1], v[2]));
        }
      }
  grid->setTransform(transform_of(g));
  grid->setName(g.name);
  grid->setGridClass(Components == 1 ? openvdb::GRID_FOG_VOLUME : openvdb::GRID_UNKNOWN);
  grid->setSaveFloatAsHalf(g.half_float);
  return grid;
}

void write_grids_in_this_process(const std::string& path, const std::vector<VdbGridToWrite>& grids) {
  initialize_openvdb();
  openvdb::GridPtrVec out;
  for (const VdbGridToWrite& g : grids) {
    const size_t voxels = size_t(std::max(g.dims[0], 0)) * size_t(std::max(g.dims[1], 0)) * size_t(std::max(g.dims[2], 0));
    if (g.values.size() != voxels * (g.vec3 ? 3 : 1))
      throw std::invalid_argument("write_vdb_grids: grid \"" + g.name + "\" has the wrong number of values");
    out.push_back(g.vec3 ? dense_to_grid<openvdb::Vec3SGrid, 3>(g) : dense_to_grid<openvdb::FloatGrid, 1>(g));
  }
  const std::string tmp = path + ".tmp";
  {
    openvdb::io::File file(tmp);
    file.write(out);
    file.close();
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
}

}  // namespace

// The child's limits for this file: unless set, 2.5 GiB (room for OpenVDB and for a grid of up to
// 2^28 voxels twice, as its tree and as bricks) plus 64 bytes a byte of file (its trees
// decompressed, then copied into bricks), at most half the machine's memory (run_isolated's
// default, applied when this is larger). A 10 KB file that asks for gigabytes is refused; a
// 2 GB file of 5·10^8 voxels may use half the machine.
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

SparseGrid read_vdb_grid_sparse(const std::string& path, const VdbGridChoice& choice,
                                std::string* note, VdbReadStats* stats) {
  check_file(path);
  check_vdb_file_structure(path);
  // The child's result: the note's length and text, then the grid.
  SparseGrid grid;
  IsolatedRunStats run;
  run_isolated(
      path, "reading the OpenVDB file",
      [&](ResultWriter& out) { read_grid_in_this_process(path, choice, out); },
      [&](std::string_view bytes) {
        std::string child_note;
        grid = decode_sparse_grid(bytes, &child_note);
        if (note && !child_note.empty()) *note = child_note;
      },
      limits_for(path), &run);
  check_grid_header(path, grid);
  if (stats) stats->child_peak_rss_bytes = run.peak_rss_bytes;
  return grid;
}

DenseGrid read_vdb_grid(const std::string& path, const VdbGridChoice& choice, std::string* note) {
  const SparseGrid grid = read_vdb_grid_sparse(path, choice, note);
  if (grid.box_voxels() > kMaxDenseGridVoxels)
    throw UserError(path, "grid " + quote(grid.name),
                    "a grid whose active bounding box has at most 2^28 voxels for a dense copy, found " +
                        std::to_string(grid.box_voxels()));
  return dense_from_sparse(grid);
}

void write_vdb_fog_volume(const std::string& path, const std::string& grid_name,
                          const std::array<int, 3>& origin, const std::array<int, 3>& dims,
                          const std::vector<float>& values, double voxel_size,
                          const std::array<double, 3>& translation, bool half_float) {
  VdbGridToWrite g;
  g.name = grid_name;
  g.origin = origin;
  g.dims = dims;
  g.values = values;
  g.voxel_size = {voxel_size, voxel_size, voxel_size};
  g.translation = translation;
  g.half_float = half_float;
  write_vdb_grids(path, {g});
}

void write_vdb_grids(const std::string& path, const std::vector<VdbGridToWrite>& grids) {
  // In a child: the parent process never starts OpenVDB or its TBB threads (isolated_call.h).
  run_isolated(
      path, "writing the OpenVDB file", [&](ResultWriter&) { write_grids_in_this_process(path, grids); },
      [](std::string_view) {}, vdb_isolation_limits());
}

}  // namespace pyro
