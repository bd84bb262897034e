// Content digests of assets and their cache: a digest is SHA-256 of the bytes (checked against
// sha256_hex of the same bytes), found again in the cache without reading the file, computed
// anew when the file is rewritten in place, and a damaged cache entry is never believed.
#include "engine/io/content_digest.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/sha256.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

TEST(ContentDigest, FileDigestIsTheSha256OfItsBytes) {
  const fs::path dir = test::scratch_dir("digest_file");
  std::string bytes;
  for (int i = 0; i < 3'000'000; ++i) bytes.push_back(char(i * 31 + 7));  // over the read block
  write_text(dir / "asset.bin", bytes);
  EXPECT_EQ(file_sha256((dir / "asset.bin").string()), sha256_hex(bytes));
}

TEST(ContentDigest, CachedUntilTheFileChangesInPlace) {
  const fs::path dir = test::scratch_dir("digest_cache");
  const fs::path asset = dir / "cloud.vdb";
  write_text(asset, "first version");
  std::string first;
  {
    DigestCache cache(dir.string());
    first = cache.file(asset.string());
    EXPECT_EQ(cache.computed(), 1);
  }
  ASSERT_TRUE(fs::exists(dir / "digests.json"));
  {
    DigestCache cache(dir.string());
    EXPECT_EQ(cache.file(asset.string()), first);
    EXPECT_EQ(cache.computed(), 0) << "read from the cache, not from the file";
  }
  // Same size, other bytes, a later modification time: a new digest.
  write_text(asset, "other version");
  fs::last_write_time(asset, fs::last_write_time(asset) + std::chrono::seconds(2));
  DigestCache cache(dir.string());
  EXPECT_EQ(cache.file(asset.string()), sha256_hex("other version"));
  EXPECT_EQ(cache.computed(), 1);
}

TEST(ContentDigest, DamagedCacheEntriesAreNotBelieved) {
  const fs::path dir = test::scratch_dir("digest_damaged");
  const fs::path asset = dir / "cloud.pyrop";
  write_text(asset, "particles");
  { DigestCache(dir.string()).file(asset.string()); }
  std::string text;
  {
    std::ifstream in(dir / "digests.json");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string real = sha256_hex("particles");
  ASSERT_NE(text.find(real), std::string::npos);
  text.replace(text.find(real), 64, std::string(63, 'a') + "Z");  // not a hex digest
  write_text(dir / "digests.json", text);
  DigestCache cache(dir.string());
  EXPECT_EQ(cache.file(asset.string()), real);
  EXPECT_EQ(cache.computed(), 1);
}

TEST(ContentDigest, FolderDigestFollowsNamesAndContentsNotHiddenFiles) {
  const fs::path dir = test::scratch_dir("digest_folder");
  fs::create_directories(dir / "fire");
  write_text(dir / "fire" / "frame_0000.png", "a");
  write_text(dir / "fire" / "flipbook.json", "{}");
  DigestCache cache("");
  const std::string base = cache.folder((dir / "fire").string());
  write_text(dir / "fire" / ".partial-123", "staging leftovers are not content");
  EXPECT_EQ(cache.folder((dir / "fire").string()), base);
  fs::rename(dir / "fire" / "frame_0000.png", dir / "fire" / "frame_0001.png");
  EXPECT_NE(cache.folder((dir / "fire").string()), base) << "a renamed frame is another flipbook";
}

}  // namespace
}  // namespace pyro
