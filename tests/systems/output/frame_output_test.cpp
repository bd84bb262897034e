// The output phase's common frame: every sink of a run gets each frame read back once, writes
// into the one staging folder, and the files move in together (or not at all); a resumed run
// draws only the frames whose files the folder does not hold finished.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/io/output_folder.h"
#include "systems/output/frame_names.h"
#include "systems/output/frame_output.h"
#include "systems/output/png_sink.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// A 2x1 frame whose pixels say how many times it was read.
class CountingSource : public FrameSource {
 public:
  ShownImage read_shown() override {
    ++shown_reads;
    return {2, 1, std::vector<uint8_t>(8, static_cast<uint8_t>(shown_reads))};
  }
  std::vector<LinearView> read_linear(bool with_depth) override {
    ++linear_reads;
    LinearView v{2, 1, std::vector<float>(8, 0.5f), {}};
    if (with_depth) v.depth = {1.0f, 2.0f};
    return {v};
  }
  bool shown_side_by_side() override { return false; }
  int shown_reads = 0, linear_reads = 0;
};

// What an embedding program might register: a text file per frame saying what it was handed.
class TextSink : public FrameSink {
 public:
  explicit TextSink(std::string tag, bool fail_at_frame_1 = false)
      : tag_(std::move(tag)), fail_(fail_at_frame_1) {}
  std::vector<std::string> files(int index) const override {
    return {frame_stem(index) + "." + tag_};
  }
  void write(OutputFrame& frame, const fs::path& staging) override {
    if (fail_ && frame.index() == 1) throw std::runtime_error("disk full");
    std::ofstream(staging / files(frame.index())[0])
        << int(frame.shown().rgba[0]) << " " << frame.linear(false)[0].rgba[0];
  }

 private:
  std::string tag_;
  bool fail_;
};

std::string sink_file_text(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string no_difference(const std::string&, const std::string&) { return ""; }

const char* kIdentity = R"({"digest": "abc", "parts": {}})";

TEST(FrameOutput, EverySinkGetsEachFrameReadBackOnce) {
  const fs::path out = test::scratch_dir("frame_output_once") / "out";
  CountingSource source;
  {
    OutputFolder folder(out.string(), kIdentity, no_difference, {});
    folder.begin();
    FrameOutput output(folder, false);
    output.add(std::make_unique<TextSink>("a"));
    output.add(std::make_unique<TextSink>("b"));
    output.add(std::make_unique<PngSink>(false));
    EXPECT_EQ(output.files(3), (std::vector<std::string>{"frame_0003.a", "frame_0003.b",
                                                         "frame_0003.png"}));
    for (int f = 0; f < 2; ++f) output.write(f, source);
    output.commit();
  }
  // Two frames: two reads of each form, however many sinks asked.
  EXPECT_EQ(source.shown_reads, 2);
  EXPECT_EQ(source.linear_reads, 2);
  EXPECT_EQ(sink_file_text(out / "frame_0001.a"), "2 0.5");
  EXPECT_EQ(sink_file_text(out / "frame_0001.b"), "2 0.5");
  EXPECT_TRUE(fs::exists(out / "frame_0001.png"));
}

TEST(FrameOutput, ASinkThatFailsLeavesTheFolderAsItWas) {
  const fs::path out = test::scratch_dir("frame_output_fail") / "out";
  fs::create_directories(out);
  CountingSource source;
  {
    OutputFolder folder(out.string(), kIdentity, no_difference, {});
    folder.begin();
    FrameOutput output(folder, false);
    output.add(std::make_unique<PngSink>(false));
    output.add(std::make_unique<TextSink>("a", true));
    output.write(0, source);
    EXPECT_THROW(output.write(1, source), std::runtime_error);
  }
  // Frame 0 was written, but nothing was moved in.
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_EQ(entry.path().filename().string()[0], '.') << entry.path();
}

TEST(FrameOutput, AResumedRunDrawsOnlyFramesWhoseFilesAreNotAllHeld) {
  const fs::path out = test::scratch_dir("frame_output_resume") / "out";
  CountingSource source;
  {
    OutputFolder folder(out.string(), kIdentity, no_difference, {});
    folder.begin();
    FrameOutput output(folder, false);
    output.add(std::make_unique<TextSink>("a"));
    for (int f = 0; f < 3; ++f) output.write(f, source);
    output.commit();
  }
  OutputFolderOptions resume;
  resume.resume = true;
  OutputFolder folder(out.string(), kIdentity, no_difference, resume);
  folder.begin();
  FrameOutput same_sinks(folder, true);
  same_sinks.add(std::make_unique<TextSink>("a"));
  EXPECT_EQ(same_sinks.frames_to_draw(0, 4), (std::vector<int>{3, 4}));
  // A sink whose files the folder does not hold makes every frame of the range drawn again.
  FrameOutput another_sink(folder, true);
  another_sink.add(std::make_unique<TextSink>("a"));
  another_sink.add(std::make_unique<TextSink>("b"));
  EXPECT_EQ(another_sink.frames_to_draw(1, 3), (std::vector<int>{1, 2, 3}));
  FrameOutput no_resume(folder, false);
  no_resume.add(std::make_unique<TextSink>("a"));
  EXPECT_EQ(no_resume.frames_to_draw(0, 1), (std::vector<int>{0, 1}));
}

}  // namespace
}  // namespace pyro
