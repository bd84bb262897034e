#pragma once
// A video of a run's frames as shown (sRGB; in left-right stereo both views side by side),
// encoded as they are rendered (engine/io/video_file.h: .mp4, .webm or .gif by the extension; a
// GIF's frames are held and encoded by finish(), with one palette made from all of them).
// The video is written to a temporary beside its path and renamed into place by finish(), which
// the common frame calls before it moves the frames in: a failed or killed run leaves no
// half-written video at the path. It needs every frame of the range: a resumed run draws the
// frames it keeps again for the video.
#include <memory>

#include "engine/io/video_file.h"
#include "systems/output/frame_sink.h"

namespace pyro {

class VideoSink : public FrameSink {
 public:
  // `quality` 0..100 (VideoWriter's mapping onto the codec's CRF).
  VideoSink(std::string path, double fps, int quality)
      : path_(std::move(path)), fps_(fps), quality_(quality) {}
  std::vector<std::string> files(int) const override { return {}; }
  bool needs_every_frame() const override { return true; }
  void write(OutputFrame& frame, const std::filesystem::path& staging) override;
  void finish() override;

 private:
  std::string path_;
  double fps_;
  int quality_;
  std::unique_ptr<VideoWriter> writer_;  // opened at the first frame, at its size
};

}  // namespace pyro
