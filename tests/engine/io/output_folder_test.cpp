// OutputFolder on hand-made identities: the manifest records each file's SHA-256 as it is moved
// in, a file whose bytes no longer have it is not held (truncated, or another frame copied over
// it), and a run whose identity names the same source file as the folder's earlier run replaces
// that run, unless the folder holds anything else.
#include "engine/io/output_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/sha256.h"
#include "engine/core/user_error.h"
#include "tests/support/file_bytes.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

std::string output_folder_test_difference(const std::string&, const std::string&) { return "its parts"; }

// An identity {"digest", "parts", ["source"]}: the digest stands for the run's content.
std::string folder_identity(const std::string& digest, const nlohmann::json& source = nullptr) {
  nlohmann::json id = {{"digest", digest}, {"parts", nlohmann::json::object()}};
  if (!source.is_null()) id["source"] = source;
  return id.dump();
}

// Runs `id` into `out`, writing each of `files` (name -> bytes) through the staging folder.
void folder_run_into(const fs::path& out, const std::string& id,
              const std::vector<std::pair<std::string, std::string>>& files) {
  OutputFolder folder(out.string(), id, output_folder_test_difference, {});
  folder.begin();
  for (const auto& [name, bytes] : files)
    std::ofstream(folder.staging().path() / name, std::ios::binary) << bytes;
  folder.commit();
}

std::vector<std::string> folder_held(const fs::path& out, const std::string& id) {
  OutputFolder folder(out.string(), id, output_folder_test_difference, {});
  return folder.held_files();
}

TEST(OutputFolder, TheManifestRecordsEachFilesSha256) {
  const fs::path out = test::scratch_dir("output_folder_digests") / "out";
  const std::string a(5000, 'a'), b = "the second frame's bytes";
  folder_run_into(out, folder_identity("run-1"), {{"frame_0000.png", a}, {"frame_0001.png", b}});
  const nlohmann::json m = nlohmann::json::parse(test::read_bytes(out / kOutputManifestName));
  ASSERT_TRUE(m.contains("sha256")) << m.dump();
  EXPECT_EQ(m["sha256"], (nlohmann::json{{"frame_0000.png", sha256_hex(a)},
                                         {"frame_0001.png", sha256_hex(b)}}));
}

TEST(OutputFolder, ADamagedOrSwappedFileIsNotHeld) {
  const fs::path out = test::scratch_dir("output_folder_damaged") / "out";
  const std::string id = folder_identity("run-1");
  folder_run_into(out, id, {{"frame_0000.png", std::string(3000, 'x')},
                     {"frame_0001.png", std::string(3000, 'y')},
                     {"frame_0002.png", std::string(3000, 'z')}});
  EXPECT_EQ(folder_held(out, id), (std::vector<std::string>{"frame_0000.png", "frame_0001.png",
                                                     "frame_0002.png"}));
  fs::resize_file(out / "frame_0000.png", 1000);  // truncated
  fs::copy_file(out / "frame_0001.png", out / "frame_0002.png",
                fs::copy_options::overwrite_existing);  // one frame copied over another
  EXPECT_EQ(folder_held(out, id), (std::vector<std::string>{"frame_0001.png"}));
  // A run of the same identity that rewrites none of them leaves no damaged file behind.
  folder_run_into(out, id, {});
  EXPECT_FALSE(fs::exists(out / "frame_0000.png"));
  EXPECT_FALSE(fs::exists(out / "frame_0002.png"));
  EXPECT_EQ(folder_held(out, id), (std::vector<std::string>{"frame_0001.png"}));
}

TEST(OutputFolder, AnEarlierRunOfTheSameSourceIsReplacedAndOthersRefused) {
  const fs::path out = test::scratch_dir("output_folder_source") / "out";
  const nlohmann::json scene = {{"path", "/s/fog.json"}, {"file", "7:42"}};
  folder_run_into(out, folder_identity("before-edit", scene),
           {{"frame_0000.png", "old 0"}, {"frame_0001.png", "old 1"}});
  // The same file, renamed into place by an editor (another inode, the same path).
  const nlohmann::json saved = {{"path", "/s/fog.json"}, {"file", "7:43"}};
  folder_run_into(out, folder_identity("after-edit", saved), {{"frame_0000.png", "new 0"}});
  EXPECT_EQ(test::read_bytes(out / "frame_0000.png"), "new 0");
  EXPECT_FALSE(fs::exists(out / "frame_0001.png")) << "the earlier render goes whole";

  const nlohmann::json other = {{"path", "/s/mist.json"}, {"file", "7:50"}};
  EXPECT_THROW(OutputFolder(out.string(), folder_identity("mist", other), output_folder_test_difference, {}), UserError);
  EXPECT_THROW(OutputFolder(out.string(), folder_identity("piped"), output_folder_test_difference, {}), UserError);
  std::ofstream(out / "notes.txt") << "the artist's";
  const nlohmann::json linked = {{"path", "/elsewhere/link.json"}, {"file", "7:43"}};
  EXPECT_THROW(OutputFolder(out.string(), folder_identity("edited-again", linked), output_folder_test_difference, {}),
               UserError)
      << "a folder holding anything else is refused";
  fs::remove(out / "notes.txt");
  folder_run_into(out, folder_identity("edited-again", linked), {{"frame_0000.png", "newer 0"}});
  EXPECT_EQ(test::read_bytes(out / "frame_0000.png"), "newer 0");
}

}  // namespace
}  // namespace pyro
