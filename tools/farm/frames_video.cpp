#include "tools/farm/frames_video.h"

#include <filesystem>
#include <memory>
#include <set>

#include "engine/core/user_error.h"
#include "engine/io/png_file.h"
#include "engine/io/video_file.h"
#include "tools/farm/farm_collect.h"

namespace pyro {

namespace {

void check_one_png_per_frame(const std::vector<std::string>& files) {
  std::set<int> frames;
  for (const std::string& name : files) {
    if (std::filesystem::path(name).extension() != ".png")
      throw UserError("--video", "", "PNG frames to encode (--format png); found " + name);
    if (!frames.insert(frame_of_file(name)).second)
      throw UserError("--video", "",
                      "one PNG per frame; frame " + std::to_string(frame_of_file(name)) +
                          " has two (stereo eyes in separate files)");
  }
}

}  // namespace

void encode_frames_video(const std::string& dir, const std::vector<std::string>& files,
                         const std::string& video, double fps, int quality) {
  check_one_png_per_frame(files);
  std::unique_ptr<VideoWriter> writer;
  int width = 0, height = 0;
  for (const std::string& name : files) {
    const PngImage image = read_png((std::filesystem::path(dir) / name).string());
    if (!writer) {
      width = image.width;
      height = image.height;
      writer = std::make_unique<VideoWriter>(video, width, height, fps, quality);
    }
    if (image.width != width || image.height != height)
      throw UserError((std::filesystem::path(dir) / name).string(), "",
                      "a frame of " + std::to_string(width) + "x" + std::to_string(height) +
                          " pixels like the first, for one video");
    writer->add_frame(image.pixels.data(), image.channels);
  }
  if (writer) writer->finish();
}

}  // namespace pyro
