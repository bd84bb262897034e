// A farm's frames cut into array tasks, and the missing frames named as ranges.
#include "tools/farm/frame_chunks.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "tools/farm/farm_collect.h"

namespace pyro {
namespace {

std::vector<std::pair<int, int>> chunk_pairs(const std::vector<FrameRange>& ranges) {
  std::vector<std::pair<int, int>> pairs;
  for (const FrameRange& r : ranges) pairs.emplace_back(r.first, r.last);
  return pairs;
}

TEST(FrameChunks, CutsARangeIntoChunksWithTheRestLast) {
  EXPECT_EQ(
      chunk_pairs(chunk_frames({0, 59}, 10)),
      (std::vector<std::pair<int, int>>{{0, 9}, {10, 19}, {20, 29}, {30, 39}, {40, 49}, {50, 59}}));
  EXPECT_EQ(chunk_pairs(chunk_frames({5, 17}, 5)),
            (std::vector<std::pair<int, int>>{{5, 9}, {10, 14}, {15, 17}}));
  EXPECT_EQ(chunk_pairs(chunk_frames({7, 7}, 10)), (std::vector<std::pair<int, int>>{{7, 7}}));
  EXPECT_EQ(chunk_pairs(chunk_frames({0, 2}, 1)),
            (std::vector<std::pair<int, int>>{{0, 0}, {1, 1}, {2, 2}}));
}

TEST(FrameChunks, ChunksCoverEveryFrameOnceForAnyChunkSize) {
  for (int chunk = 1; chunk <= 25; ++chunk) {
    const std::vector<FrameRange> chunks = chunk_frames({3, 61}, chunk);
    int next = 3;
    for (const FrameRange& c : chunks) {
      EXPECT_EQ(c.first, next) << "chunk " << chunk;
      EXPECT_LE(c.count(), chunk);
      next = c.last + 1;
    }
    EXPECT_EQ(next, 62) << "chunk " << chunk;
    EXPECT_EQ(static_cast<int>(chunks.size()), (59 + chunk - 1) / chunk);
  }
}

TEST(FrameChunks, AChunkLargerThanTheIntRangeLeftDoesNotOverflow) {
  EXPECT_EQ(chunk_pairs(chunk_frames({999990, 999999}, 2147483647)),
            (std::vector<std::pair<int, int>>{{999990, 999999}}));
  EXPECT_THROW(chunk_frames({0, 9}, 0), std::invalid_argument);
}

TEST(FrameChunks, ResubmittedRangesAreChunkedApart) {
  EXPECT_EQ(chunk_pairs(chunk_ranges({{20, 29}, {45, 47}}, 4)),
            (std::vector<std::pair<int, int>>{{20, 23}, {24, 27}, {28, 29}, {45, 47}}));
}

TEST(FrameChunks, MissingFramesAreNamedAsMaximalRanges) {
  std::set<int> present;
  for (int f = 0; f < 60; ++f)
    if (f < 20 || f > 29) present.insert(f);
  EXPECT_EQ(ranges_text(missing_ranges({0, 59}, present)), "20:29");
  present.erase(0);
  present.erase(59);
  present.erase(41);
  EXPECT_EQ(ranges_text(missing_ranges({0, 59}, present)), "0:0, 20:29, 41:41, 59:59");
  EXPECT_TRUE(missing_ranges({0, 9}, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}).empty());
  // Frames outside the range count for nothing.
  EXPECT_EQ(ranges_text(missing_ranges({10, 12}, {0, 1, 13})), "10:12");
}

TEST(FrameChunks, FilesAreAssignedToTheirFrame) {
  EXPECT_EQ(frame_of_file("frame_0042.png"), 42);
  EXPECT_EQ(frame_of_file("frame_0007_left.exr"), 7);
  EXPECT_EQ(frame_of_file("frame_123456.png"), 123456);
  EXPECT_EQ(frame_of_file("frame_.png"), -1);
  EXPECT_EQ(frame_of_file("frame_12"), -1);
  EXPECT_EQ(frame_of_file("frame_12x.png"), -1);
  EXPECT_EQ(frame_of_file("SHA256SUMS"), -1);
  EXPECT_EQ(frame_of_file(".pyro_manifest.json"), -1);
}

}  // namespace
}  // namespace pyro
