// Imports check their output: a grid holding a non-finite or absurd density is refused naming the
// file, the grid and the voxel; and damaged copies of the shared VDB files (16 random bytes
// overwritten, seeded) either import with exit 0 into a particle file the loader accepts, or are
// refused with exit 2 and a message. Never exit 0 with a file the loader refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/io/vdb_reader.h"
#include "tests/support/file_bytes.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// An 8^3 fog volume at density 0.3 with one voxel, (5, 2, 6) from origin (10, 20, 30), at `bad`.
std::string damaged_grid(const fs::path& dir, float bad) {
  const std::string path = (dir / "damaged.vdb").string();
  std::vector<float> v(8 * 8 * 8, 0.3f);
  v[(6 * 8 + 2) * 8 + 5] = bad;
  write_vdb_fog_volume(path, "density", {10, 20, 30}, {8, 8, 8}, v, 0.5, {0, 0, 0});
  return path;
}

TEST(VdbDamagedImport, NonFiniteOrAbsurdDensityIsRefusedNamingTheGridAndVoxel) {
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity(), 3.7e30f}) {
    const fs::path dir = test::scratch_dir("bad_density");
    const std::string path = damaged_grid(dir, bad);
    try {
      read_vdb_grid(path);
      ADD_FAILURE() << "a grid holding " << bad << " was read";
    } catch (const UserError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_EQ(e.place(), "grid \"density\", voxel (15, 22, 36)") << e.what();
    }
    const fs::path out = dir / "out.pyrop";
    const auto r = test::run_pyro({"import-vdb", path, "--out", out.string(), "--width", "32",
                                   "--height", "32"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("voxel (15, 22, 36)"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(VdbDamagedImport, LargestSaneDensityIsRead) {
  const fs::path dir = test::scratch_dir("large_density");
  EXPECT_NO_THROW(read_vdb_grid(damaged_grid(dir, 1e6f)));
}

using test::read_bytes;

// PYRO_DAMAGED_COPIES (default 4) copies of every shared VDB file with 16 bytes overwritten.
TEST(VdbDamagedImport, DamagedSharedFilesImportLoadablyOrAreRefused) {
  const fs::path shared = fs::path(PYRO_SHARED_DATA_DIR) / "vdb";
  if (!fs::is_directory(shared)) GTEST_SKIP() << "no third-party VDB files at " << shared;
  const char* env = std::getenv("PYRO_DAMAGED_COPIES");
  const int copies = env ? std::atoi(env) : 4;
  const fs::path dir = test::scratch_dir("damaged_shared");
  uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&state] {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;  // xorshift64 (Marsaglia 2003)
    return state;
  };
  int imported = 0, refused = 0;
  for (const auto& entry : fs::directory_iterator(shared)) {
    if (entry.path().extension() != ".vdb") continue;
    const std::string original = read_bytes(entry.path());
    for (int c = 0; c < copies; ++c) {
      std::string bytes = original;
      for (int k = 0; k < 16; ++k) bytes[next() % bytes.size()] = static_cast<char>(next());
      const fs::path copy = dir / "copy.vdb", out = dir / "copy.pyrop";
      std::ofstream(copy, std::ios::binary) << bytes;
      fs::remove(out);
      const auto r = test::run_pyro({"import-vdb", copy.string(), "--out", out.string(),
                                     "--width", "32", "--height", "32"});
      if (r.exit_code == 0) {
        ++imported;
        EXPECT_NO_THROW(read_particle_file(out.string()))
            << entry.path().filename() << " copy " << c << " imported into a refused file";
      } else {
        ++refused;
        EXPECT_EQ(r.exit_code, 2) << entry.path().filename() << " copy " << c << ": " << r.err;
        EXPECT_FALSE(r.err.empty());
        EXPECT_FALSE(fs::exists(out));
      }
    }
  }
  RecordProperty("imported", imported);
  RecordProperty("refused", refused);
  std::printf("damaged VDB copies: %d imported (loadable), %d refused with exit 2\n", imported,
              refused);
}

}  // namespace
}  // namespace pyro
