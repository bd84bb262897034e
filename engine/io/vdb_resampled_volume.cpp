// The second translation unit that includes OpenVDB (with vdb_reader.cpp): OpenVDB runs here only
// in the child process of run_isolated.
#include "engine/io/vdb_resampled_volume.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cerrno>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include "engine/core/user_error.h"
#include "engine/io/io_error.h"
#include "engine/io/isolated_call.h"
#include "engine/io/vdb_file_check.h"

namespace pyro {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;
constexpr int kLeaf = 8;

int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// Where fine voxel I lies in the source: its lower neighbour's local index and the weight of the
// upper one, along one axis.
struct AxisSample {
  int i0 = 0;
  float t = 0.0f;
};

class Resampler {
 public:
  Resampler(const DenseGrid& source, double scale) : src_(source), scale_(scale) {
    // Fine voxels whose source coordinate lies in (origin - 1, origin + n): the only ones that
    // can be non-zero.
    for (int a = 0; a < 3; ++a) {
      lo_[a] = int64_t(std::floor((source.origin[a] - 0.5) * scale - 0.5)) - 1;
      hi_[a] = int64_t(std::ceil((source.origin[a] + source.dims[a] + 0.5) * scale - 0.5)) + 1;
      leaf_lo_[a] = floor_div(lo_[a], kLeaf) * kLeaf;
      leaves_[a] = int((hi_[a] - leaf_lo_[a]) / kLeaf + 1);
    }
  }
  int leaves(int a) const { return leaves_[a]; }

  // The leaf (lx, ly, lz) of the fine grid's leaf lattice, null when all its voxels are 0.
  LeafT* make_leaf(int lx, int ly, int lz) const {
    const int64_t o[3] = {leaf_lo_[0] + int64_t(lx) * kLeaf, leaf_lo_[1] + int64_t(ly) * kLeaf,
                          leaf_lo_[2] + int64_t(lz) * kLeaf};
    AxisSample s[3][kLeaf];
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < kLeaf; ++k) {
        const double u = (double(o[a] + k) + 0.5) / scale_ - 0.5 - src_.origin[a];
        const double f = std::floor(u);
        s[a][k] = {int(std::max(-2.0, std::min(f, double(src_.dims[a]) + 1.0))), float(u - f)};
      }
    if (!touches_density(s)) return nullptr;
    float v[kLeaf][kLeaf][kLeaf];  // [x][y][z], OpenVDB's order within a leaf
    bool any = false;
    for (int x = 0; x < kLeaf; ++x)
      for (int y = 0; y < kLeaf; ++y)
        for (int z = 0; z < kLeaf; ++z) {
          v[x][y][z] = sample(s[0][x], s[1][y], s[2][z]);
          any = any || v[x][y][z] != 0.0f;
        }
    if (!any) return nullptr;
    auto* leaf = new LeafT(openvdb::Coord(int(o[0]), int(o[1]), int(o[2])), 0.0f, false);
    for (int x = 0; x < kLeaf; ++x)
      for (int y = 0; y < kLeaf; ++y)
        for (int z = 0; z < kLeaf; ++z)
          if (v[x][y][z] != 0.0f) leaf->setValueOn(openvdb::Index((x << 6) | (y << 3) | z), v[x][y][z]);
    return leaf;
  }

 private:
  float value(int x, int y, int z) const {
    if (x < 0 || y < 0 || z < 0 || x >= src_.dims[0] || y >= src_.dims[1] || z >= src_.dims[2]) return 0.0f;
    return src_.at(x, y, z);
  }
  // Whether any source voxel the leaf's samples read holds density.
  bool touches_density(const AxisSample (&s)[3][kLeaf]) const {
    for (int z = s[2][0].i0; z <= s[2][kLeaf - 1].i0 + 1; ++z)
      for (int y = s[1][0].i0; y <= s[1][kLeaf - 1].i0 + 1; ++y)
        for (int x = s[0][0].i0; x <= s[0][kLeaf - 1].i0 + 1; ++x)
          if (value(x, y, z) != 0.0f) return true;
    return false;
  }
  float sample(const AxisSample& sx, const AxisSample& sy, const AxisSample& sz) const {
    const int x = sx.i0, y = sy.i0, z = sz.i0;
    const float c00 = value(x, y, z) + sx.t * (value(x + 1, y, z) - value(x, y, z));
    const float c10 = value(x, y + 1, z) + sx.t * (value(x + 1, y + 1, z) - value(x, y + 1, z));
    const float c01 = value(x, y, z + 1) + sx.t * (value(x + 1, y, z + 1) - value(x, y, z + 1));
    const float c11 = value(x, y + 1, z + 1) + sx.t * (value(x + 1, y + 1, z + 1) - value(x, y + 1, z + 1));
    const float c0 = c00 + sy.t * (c10 - c00), c1 = c01 + sy.t * (c11 - c01);
    return c0 + sz.t * (c1 - c0);
  }

  const DenseGrid& src_;
  double scale_;
  int64_t lo_[3], hi_[3], leaf_lo_[3];
  int leaves_[3];
};

// The source's index-to-world map composed with fine index -> source index, as OpenVDB's
// row-vector matrix (translation in row 3).
openvdb::math::Mat4d fine_index_to_world(const DenseGrid& source, double scale) {
  glm::dmat4 fine_to_source(1.0 / scale);
  fine_to_source[3] = glm::dvec4(glm::dvec3(0.5 / scale - 0.5), 1.0);
  const glm::dmat4 m = source.index_to_world * fine_to_source;
  openvdb::math::Mat4d out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out(r, c) = m[r][c];
  return out;
}

void say(int fd, const std::string& line) {
  if (fd < 0) return;
  const std::string text = line + "\n";
  if (::write(fd, text.data(), text.size()) < 0) {
    // Progress is a courtesy: a closed descriptor does not stop the work.
  }
}

// fsync of a written file: a full disk or an I/O error that the writer did not see shows here.
void flush_to_disk(const std::string& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw IoError(file, "open the written file", errno);
  const int rc = ::fsync(fd);
  const int error = errno;
  ::close(fd);
  if (rc != 0) throw IoError(file, "flush the file to disk (fsync)", error);
}

// Builds the fine grid one layer of leaves at a time (the layer's leaves made on TBB's threads,
// then added to the tree in order), then writes it.
void write_in_this_process(const std::string& path, const std::string& grid_name, const DenseGrid& source,
                           double scale, int fd, const std::string& label, ResultWriter& out) {
  openvdb::initialize();
  const Resampler resampler(source, scale);
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
  const int nx = resampler.leaves(0), ny = resampler.leaves(1), nz = resampler.leaves(2);
  std::vector<LeafT*> layer(size_t(nx) * ny);
  int said = 0;
  for (int lz = 0; lz < nz; ++lz) {
    tbb::parallel_for(tbb::blocked_range<int>(0, ny), [&](const tbb::blocked_range<int>& r) {
      for (int ly = r.begin(); ly < r.end(); ++ly)
        for (int lx = 0; lx < nx; ++lx) layer[size_t(ly) * nx + lx] = resampler.make_leaf(lx, ly, lz);
    });
    for (LeafT* leaf : layer)
      if (leaf) grid->tree().addLeaf(leaf);
    for (; said < 10 && (lz + 1) * 10 >= (said + 1) * nz; ++said)
      say(fd, label + std::to_string((said + 1) * 10) + "% of the leaf layers");
  }
  grid->setTransform(openvdb::math::Transform::createLinearTransform(fine_index_to_world(source, scale)));
  grid->setName(grid_name);
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  const uint64_t active = grid->activeVoxelCount(), leaves = grid->tree().leafCount();
  say(fd, label + "compressing and writing " + std::to_string(active) + " active voxels");
  const std::string tmp = path + ".tmp";
  {
    openvdb::io::File file(tmp);
    file.write({grid});
    file.close();
  }
  // OpenVDB's writer does not report a failed write (a full disk leaves a truncated file): the
  // file is flushed and its structure checked before it takes the destination's name.
  std::error_code ec;
  try {
    flush_to_disk(tmp);
    check_vdb_file_structure(tmp);
  } catch (const UserError&) {
    // Cut short by the file system (the writer saw no error): the environment's failure.
    struct statvfs space {};
    const bool full = ::statvfs(std::filesystem::path(tmp).parent_path().c_str(), &space) == 0 && space.f_bavail == 0;
    std::filesystem::remove(tmp, ec);
    throw IoError(tmp, "write the whole OpenVDB file (it came out incomplete)", full ? ENOSPC : EIO);
  } catch (...) {
    std::filesystem::remove(tmp, ec);
    throw;
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
  out.append(&active, sizeof active);
  out.append(&leaves, sizeof leaves);
}

}  // namespace

VdbResampleReport write_vdb_resampled_fog_volume(const std::string& path, const std::string& grid_name,
                                                 const DenseGrid& source, double scale, int progress_fd,
                                                 const std::string& progress_label) {
  if (!(scale > 0.0 && scale < 1e4)) throw UserError(path, "", "a resampling scale in (0, 1e4)");
  if (source.empty()) throw UserError(source.file, "", "a grid with voxels to resample");
  // The child's stderr is captured (isolated_call.h): progress goes to a copy of the descriptor.
  const int fd = progress_fd >= 0 ? ::dup(progress_fd) : -1;
  VdbResampleReport report;
  IsolatedRunStats run;
  try {
    run_isolated(
        path, "writing the resampled OpenVDB file",
        [&](ResultWriter& out) { write_in_this_process(path, grid_name, source, scale, fd, progress_label, out); },
        [&](std::string_view bytes) {
          if (bytes.size() != 2 * sizeof(uint64_t)) throw std::runtime_error("resample: short result");
          std::memcpy(&report.active_voxels, bytes.data(), sizeof(uint64_t));
          std::memcpy(&report.leaves, bytes.data() + sizeof(uint64_t), sizeof(uint64_t));
        },
        vdb_isolation_limits(), &run);
  } catch (...) {
    if (fd >= 0) ::close(fd);
    throw;
  }
  if (fd >= 0) ::close(fd);
  report.child_peak_rss_bytes = run.peak_rss_bytes;
  std::error_code ec;
  report.file_bytes = std::filesystem::file_size(path, ec);
  return report;
}

}  // namespace pyro
