#include "engine/io/vdb_file_check.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

#include "engine/core/user_error.h"

namespace pyro {

namespace {

// Oldest and newest file format versions OpenVDB 10 reads (io.h: OPENVDB_FILE_VERSION_*).
constexpr uint32_t kOldestVersion = 213, kNewestVersion = 224;

class Cursor {
 public:
  Cursor(const std::string& path, std::vector<char> bytes) : path_(path), b_(std::move(bytes)) {}
  size_t pos() const { return p_; }
  size_t size() const { return b_.size(); }
  void need(uint64_t n, const char* what) {
    if (n > b_.size() - p_)
      throw UserError(path_, "", std::string("truncated or corrupt OpenVDB file: ") + what +
                                     " at byte " + std::to_string(p_) + " needs " +
                                     std::to_string(n) + " bytes, only " +
                                     std::to_string(b_.size() - p_) + " remain");
  }
  template <class T>
  T read(const char* what) {
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, b_.data() + p_, sizeof(T));
    p_ += sizeof(T);
    return v;
  }
  void skip(uint64_t n, const char* what) {
    need(n, what);
    p_ += n;
  }
  std::string string(const char* what) {
    const uint32_t n = read<uint32_t>(what);
    need(n, what);
    std::string s(b_.data() + p_, n);
    p_ += n;
    return s;
  }
  void seek(uint64_t to, const char* what) {
    if (to > b_.size())
      throw UserError(path_, "", std::string("truncated or corrupt OpenVDB file: ") + what +
                                     " points to byte " + std::to_string(to) +
                                     " but the file has " + std::to_string(b_.size()) + " bytes");
    p_ = to;
  }

 private:
  std::string path_;
  std::vector<char> b_;
  size_t p_ = 0;
};

}  // namespace

void check_vdb_file_structure(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw UserError(path, "", "cannot open VDB file");
  const std::streamoff size = in.tellg();
  in.seekg(0);
  std::vector<char> bytes(static_cast<size_t>(std::max<std::streamoff>(size, 0)));
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
    throw UserError(path, "", "cannot read VDB file");
  Cursor c(path, std::move(bytes));
  if (c.read<int64_t>("the magic number") != 0x56444220)
    throw UserError(path, "", "not an OpenVDB file: the magic number 0x56444220 is missing");
  const uint32_t version = c.read<uint32_t>("the file version");
  if (version < kOldestVersion || version > kNewestVersion)
    throw UserError(path, "", "an OpenVDB file format version in [" + std::to_string(kOldestVersion) +
                                  ", " + std::to_string(kNewestVersion) + "], found " +
                                  std::to_string(version));
  c.skip(8, "the library version");
  const char has_offsets = c.read<char>("the grid-offsets flag");
  if (version >= 220 && version < 222) c.skip(1, "the compression flag");
  c.skip(36, "the file UUID");
  const int32_t meta_count = c.read<int32_t>("the file metadata count");
  if (meta_count < 0) throw UserError(path, "", "corrupt OpenVDB file: negative metadata count");
  for (int32_t i = 0; i < meta_count; ++i) {
    c.string("a file metadata name");
    c.string("a file metadata type");
    const uint32_t n = c.read<uint32_t>("a file metadata size");
    c.skip(n, "a file metadata value");
  }
  if (!has_offsets) return;  // pre-2.0 layout without offsets: nothing more to check cheaply
  const int32_t grids = c.read<int32_t>("the grid count");
  if (grids < 0) throw UserError(path, "", "corrupt OpenVDB file: negative grid count");
  uint64_t end = c.pos();
  for (int32_t g = 0; g < grids; ++g) {
    const std::string name = c.string("a grid name");
    c.string("a grid type");
    c.string("a grid's instance parent");
    const int64_t grid_pos = c.read<int64_t>("a grid offset");
    const int64_t block_pos = c.read<int64_t>("a grid offset");
    const int64_t end_pos = c.read<int64_t>("a grid offset");
    if (!(int64_t(c.pos()) <= grid_pos && grid_pos <= block_pos && block_pos <= end_pos))
      throw UserError(path, "", "corrupt OpenVDB file: grid " + std::to_string(g) +
                                    " has inconsistent offsets");
    c.seek(uint64_t(end_pos), ("the end of grid " + std::to_string(g)).c_str());
    end = uint64_t(end_pos);
  }
  if (end != c.size())
    throw UserError(path, "", "corrupt OpenVDB file: the last grid ends at byte " + std::to_string(end) +
                                  " but the file has " + std::to_string(c.size()) + " bytes");
}

}  // namespace pyro
