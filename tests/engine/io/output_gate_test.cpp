// The gate every output path passes (engine/io/output_gate.h): each rule refuses what it should,
// through symbolic and hard links, and lets through what it should.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/user_error.h"
#include "engine/io/folder_output_kind.h"
#include "engine/io/folder_replacement.h"
#include "engine/io/output_gate.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

void write_output_gate_file(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// The refusal's message, or "" when the gate lets the outputs through.
std::string gate_refusal(const OutputGate& gate) {
  try {
    gate.check();
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

FolderOutputKind test_kind() { return {"test bake", {".partial-*"}, {"frame_*.png", "bake.json"}}; }

OutputPath folder_output(const fs::path& p, bool overwrite = false) {
  return {p.string(), "--out", OutputShape::folder, test_kind(), overwrite};
}

TEST(OutputGate, AnOutputIsNeverAnInputThroughLinks) {
  const fs::path dir = test::scratch_dir("gate_input");
  write_output_gate_file(dir / "scene.json", "{}");
  fs::create_symlink(dir / "scene.json", dir / "soft.json");
  fs::create_hard_link(dir / "scene.json", dir / "hard.json");
  for (const char* name : {"scene.json", "soft.json", "hard.json"}) {
    const std::string why = gate_refusal(OutputGate().reads((dir / "scene.json").string(), "the scene file")
                                        .writes_file((dir / name).string(), "--trace"));
    EXPECT_NE(why.find("at --trace: an output path that is none of the command's inputs; it is the scene file"),
              std::string::npos) << name << ": " << why;
  }
  EXPECT_EQ(gate_refusal(OutputGate().reads((dir / "scene.json").string(), "the scene file")
                        .writes_file((dir / "trace.json").string(), "--trace")), "");
}

TEST(OutputGate, AnOutputIsNeverInsideAnInputFolderNorHoldsAnInput) {
  const fs::path dir = test::scratch_dir("gate_folders");
  fs::create_directories(dir / "in.pyroseq" / "cache");
  write_output_gate_file(dir / "in.pyroseq" / "smoke_0001.vdb", "vdb");
  fs::create_symlink(dir / "in.pyroseq", dir / "alias");
  OutputGate inside;
  inside.reads((dir / "in.pyroseq").string(), "the sequence's folder").writes(folder_output(dir / "alias" / "cache"));
  EXPECT_NE(gate_refusal(inside).find("lies inside the sequence's folder"), std::string::npos) << gate_refusal(inside);
  OutputGate holds;
  holds.reads((dir / "in.pyroseq" / "smoke_0001.vdb").string(), "a member").writes(folder_output(dir / "in.pyroseq"));
  EXPECT_NE(gate_refusal(holds).find("an output folder that holds none of the command's inputs; it holds a member"),
            std::string::npos) << gate_refusal(holds);
  OutputGate beside;
  beside.reads((dir / "in.pyroseq").string(), "the sequence's folder").writes(folder_output(dir / "out.pyroseq"));
  EXPECT_EQ(gate_refusal(beside), "");
}

TEST(OutputGate, DeviceNodesFifosAndSocketsAreRefused) {
  const fs::path dir = test::scratch_dir("gate_special");
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0644), 0);
  const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::snprintf(address.sun_path, sizeof address.sun_path, "%s", (dir / "socket").c_str());
  ASSERT_EQ(::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  std::vector<std::string> special = {"fifo", "socket"};
  if (::mknod((dir / "null").c_str(), S_IFCHR | 0666, ::makedev(1, 3)) == 0) special.push_back("null");
  for (const std::string& name : special) {
    const std::string why = gate_refusal(OutputGate().writes_file((dir / name).string(), "--out"));
    EXPECT_NE(why.find("which is never replaced by an output"), std::string::npos) << name << ": " << why;
  }
  ::close(s);
  EXPECT_EQ(gate_refusal(OutputGate().writes({"-", "--out", OutputShape::file, {}, false, true})), "");
}

TEST(OutputGate, ShapesAndFoldersAreChecked) {
  const fs::path dir = test::scratch_dir("gate_shapes");
  fs::create_directory(dir / "folder");
  write_output_gate_file(dir / "file", "x");
  EXPECT_NE(gate_refusal(OutputGate().writes_file((dir / "folder").string(), "--video")).find("found a folder"),
            std::string::npos);
  EXPECT_NE(gate_refusal(OutputGate().writes(folder_output(dir / "file"))).find("found a file"), std::string::npos);
  EXPECT_NE(gate_refusal(OutputGate().writes_file((dir / "missing" / "x.png").string(), "--image"))
                .find("an existing folder to write the output into, found none"),
            std::string::npos);
}

TEST(OutputGate, AFolderOutputHoldsNothingButEarlierOutputsOfItsKind) {
  const fs::path dir = test::scratch_dir("gate_contents");
  const fs::path out = dir / "bake";
  fs::create_directory(out);
  EXPECT_EQ(gate_refusal(OutputGate().writes(folder_output(out))), "");  // empty
  write_output_gate_file(out / "frame_0000.png", "png");
  write_output_gate_file(out / "bake.json", "{}");
  EXPECT_EQ(gate_refusal(OutputGate().writes(folder_output(out))), "");  // an earlier bake, unrecorded
  write_output_gate_file(out / "thesis.txt", "precious");
  const std::string why = gate_refusal(OutputGate().writes(folder_output(out)));
  EXPECT_NE(why.find("\"thesis.txt\", which no test bake output wrote"), std::string::npos) << why;
  EXPECT_EQ(gate_refusal(OutputGate().writes(folder_output(out, true))), "");
  // A manifest of another kind.
  fs::remove(out / "thesis.txt");
  write_output_gate_file(out / kFolderOutputManifest, R"({"kind": "render", "files": ["frame_0000.png", "bake.json"]})");
  EXPECT_NE(gate_refusal(OutputGate().writes(folder_output(out))).find("it holds a render output"), std::string::npos);
}

TEST(OutputGate, TwoOutputsNeverShareAPath) {
  const fs::path dir = test::scratch_dir("gate_pairs");
  fs::create_directory(dir / "frames");
  fs::create_symlink(dir, dir / "here");
  OutputGate same;
  same.writes_file((dir / "same.mp4").string(), "--video").writes_file((dir / "here" / "same.mp4").string(), "--trace");
  EXPECT_NE(gate_refusal(same).find("at --trace: a path of its own; it is also --video's"), std::string::npos) << gate_refusal(same);
  OutputGate inside;
  inside.writes(folder_output(dir / "frames")).writes_file((dir / "frames" / "trace.json").string(), "--trace");
  EXPECT_NE(gate_refusal(inside).find("an output path outside"), std::string::npos) << gate_refusal(inside);
  OutputGate container;
  container.writes({(dir / "charts").string(), "--out", OutputShape::container})
      .writes_file((dir / "charts" / "scale.csv").string(), "--out");
  EXPECT_EQ(gate_refusal(container), "");  // a container's own files, in a folder it creates
}

TEST(OutputGate, ImageSizesAreThoseTheReadersTake) {
  EXPECT_NO_THROW(check_image_size("--atlas", "an atlas", kMaxImageSide, 48));
  EXPECT_THROW(check_image_size("--atlas", "an atlas", 19200, 48), UserError);
  EXPECT_THROW(check_image_size("--atlas", "an atlas", 1000LL * 256, 1000LL * 384), UserError);
  EXPECT_THROW(check_memory_need("--frames", "frames", int64_t(1) << 62), UserError);
  EXPECT_NO_THROW(check_memory_need("--frames", "frames", int64_t(1) << 20));
}

// With --overwrite a replaced folder keeps every file no output wrote; the new one records its
// kind and files, so the next run replaces it without asking.
TEST(OutputGate, AReplacedFolderKeepsTheUsersFiles) {
  const fs::path dir = test::scratch_dir("gate_replacement");
  const fs::path out = dir / "bake";
  fs::create_directories(out / "notes");
  write_output_gate_file(out / "frame_0009.png", "old frame");
  write_output_gate_file(out / "notes" / "thesis.txt", "precious");
  EXPECT_THROW(FolderReplacement(out.string(), test_kind()), UserError);
  {
    FolderReplacement r(out.string(), test_kind(), true);
    write_output_gate_file(r.path() / "frame_0000.png", "new frame");
    r.commit();
  }
  EXPECT_TRUE(fs::exists(out / "frame_0000.png"));
  EXPECT_TRUE(fs::exists(out / "frame_0009.png"));  // not an output: no manifest named it
  std::ifstream kept(out / "notes" / "thesis.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "precious");
  const FolderOutputContents c = read_folder_output(out, test_kind());
  EXPECT_EQ(c.held_kind, "test bake");
  EXPECT_EQ(c.outputs, (std::vector<std::string>{".pyro_manifest.json", "frame_0000.png"}));
  EXPECT_EQ(c.foreign, (std::vector<std::string>{"frame_0009.png", "notes/thesis.txt"}));
}

}  // namespace
}  // namespace pyro
