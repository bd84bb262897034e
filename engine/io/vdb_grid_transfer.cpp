#include "engine/io/vdb_grid_transfer.h"

#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace pyro {

namespace {

class Writer {
 public:
  explicit Writer(ResultWriter& out) : out_(out) {}
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.append(&v, sizeof v);
  }
  void put(const std::string& s) {
    put<uint64_t>(s.size());
    out_.append(s.data(), s.size());
  }

 private:
  ResultWriter& out_;
};

class Reader {
 public:
  explicit Reader(std::string_view in) : in_(in) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    T v;
    std::memcpy(&v, in_.data() + pos_, sizeof v);
    pos_ += sizeof v;
    return v;
  }
  std::string get_string() {
    const uint64_t n = get<uint64_t>();
    need(n);
    std::string s(in_.data() + pos_, n);
    pos_ += n;
    return s;
  }
  template <class T>
  void get_array(std::vector<T>& v, uint64_t n) {
    if (n > (in_.size() - pos_) / sizeof(T)) throw std::runtime_error("vdb transfer: short array");
    v.resize(n);
    if (n > 0) std::memcpy(v.data(), in_.data() + pos_, n * sizeof(T));  // an empty grid: no data
    pos_ += n * sizeof(T);
  }
  size_t pos() const { return pos_; }
  void skip(size_t n) {
    need(n);
    pos_ += n;
  }
  void done() const {
    if (pos_ != in_.size()) throw std::runtime_error("vdb transfer: trailing bytes");
  }

 private:
  void need(uint64_t n) const {
    if (n > in_.size() - pos_) throw std::runtime_error("vdb transfer: short message");
  }
  std::string_view in_;
  size_t pos_ = 0;
};

// Pads the result so that what follows starts at a multiple of 4 bytes from the start of the
// result file (which is page-aligned): the values are filled in place as floats.
void align_to_float(ResultWriter& out) { out.extend((4 - out.size() % 4) % 4); }

}  // namespace

void write_grid_infos(ResultWriter& out, const std::vector<VdbGridInfo>& grids) {
  Writer w(out);
  w.put<uint64_t>(grids.size());
  for (const VdbGridInfo& g : grids) {
    w.put(g.index);
    w.put(g.name);
    w.put(g.type);
    w.put(g.value_type);
    w.put(g.grid_class);
    w.put(g.half_float);
    w.put(g.voxel_size);
    w.put(g.affine);
    w.put(g.index_to_world);
    w.put(g.active_voxels);
    w.put(g.bbox_min);
    w.put(g.bbox_max);
  }
}

std::vector<VdbGridInfo> decode_grid_infos(std::string_view bytes) {
  Reader r(bytes);
  const uint64_t n = r.get<uint64_t>();
  std::vector<VdbGridInfo> grids;
  for (uint64_t i = 0; i < n; ++i) {
    VdbGridInfo g;
    g.index = r.get<int>();
    g.name = r.get_string();
    g.type = r.get_string();
    g.value_type = r.get_string();
    g.grid_class = r.get_string();
    g.half_float = r.get<bool>();
    g.voxel_size = r.get<std::array<double, 3>>();
    g.affine = r.get<bool>();
    g.index_to_world = r.get<glm::dmat4>();
    g.active_voxels = r.get<uint64_t>();
    g.bbox_min = r.get<std::array<int, 3>>();
    g.bbox_max = r.get<std::array<int, 3>>();
    grids.push_back(std::move(g));
  }
  r.done();
  return grids;
}

float* begin_sparse_grid(ResultWriter& out, const std::string& note, const GridHeader& h,
                         const std::vector<int32_t>& slots, uint64_t bricks) {
  Writer w(out);
  w.put(note);
  w.put(h.file);
  w.put(h.name);
  w.put(h.file_index);
  w.put(h.index_to_world);
  w.put(h.voxel_size);
  w.put(h.converted_from_level_set);
  w.put(h.half_float);
  w.put(h.origin);
  w.put(h.dims);
  w.put<uint64_t>(slots.size());
  out.append(slots.data(), slots.size() * sizeof(int32_t));
  w.put<uint64_t>(bricks);
  align_to_float(out);
  return reinterpret_cast<float*>(out.extend(bricks * SparseGrid::kBrickVoxels * sizeof(float)));
}

void end_sparse_grid(ResultWriter& out, uint64_t active_voxels, float max_value) {
  Writer w(out);
  w.put(active_voxels);
  w.put(max_value);
}

SparseGrid decode_sparse_grid(std::string_view bytes, std::string* note) {
  // `bytes` starts one byte into the result file (after the run_isolated tag), so the padding
  // before the values is counted from there.
  Reader r(bytes);
  SparseGrid g;
  const std::string n = r.get_string();
  if (note) *note = n;
  g.file = r.get_string();
  g.name = r.get_string();
  g.file_index = r.get<int>();
  g.index_to_world = r.get<glm::dmat4>();
  g.voxel_size = r.get<std::array<double, 3>>();
  g.converted_from_level_set = r.get<bool>();
  g.half_float = r.get<bool>();
  g.origin = r.get<std::array<int, 3>>();
  g.dims = r.get<std::array<int, 3>>();
  for (int d : g.dims)
    if (d < 0) throw std::runtime_error("vdb transfer: negative dimension");
  g.brick_dims = brick_dims_for(g.dims);
  const uint64_t table = box_bricks(g.brick_dims);
  if (table > SparseGrid::kMaxBoxBricks || r.get<uint64_t>() != table)
    throw std::runtime_error("vdb transfer: brick table of the wrong size");
  r.get_array(g.slots, table);
  const uint64_t bricks = r.get<uint64_t>();
  for (int32_t s : g.slots)
    if (s < -1 || (s >= 0 && uint64_t(s) >= bricks)) throw std::runtime_error("vdb transfer: brick slot out of range");
  r.skip((4 - (r.pos() + 1) % 4) % 4);
  if (bricks > (bytes.size() - r.pos()) / (SparseGrid::kBrickVoxels * sizeof(float)))
    throw std::runtime_error("vdb transfer: short bricks");
  r.get_array(g.values, bricks * SparseGrid::kBrickVoxels);
  g.active_voxels = r.get<uint64_t>();
  g.max_value = r.get<float>();
  r.done();
  return g;
}

}  // namespace pyro
