#pragma once
// Video output, encoded frame by frame as a render goes, through libav (FFmpeg's libraries, seen
// only by this module's sources). The container and codec follow the file's extension:
//   .mp4   H.264 (libx264), yuv420p, BT.709 limited range. 4:2:0 H.264 has no odd sizes: an odd
//          width or height is padded to even by repeating the last column or row, so the video
//          is then one pixel wider or taller than the frames.
//   .webm  VP9 (libvpx-vp9), yuv420p, BT.709 limited range.
//   .gif   GIF with one palette of 256 colours made from the pixels of every frame and each
//          pixel its nearest palette colour, undithered (engine/io/palette_quantizer.h); the
//          quality does not apply. The frames are held in memory (3 bytes a pixel each) and
//          encoded by finish(), which needs them all to make the palette. GIF frame delays are
//          in hundredths of a second.
// Quality 0..100 maps linearly onto the encoder's constant-rate factor (CRF, lower is better):
// crf = round(max_crf * (100 - quality) / 100), max_crf 51 for x264 and 63 for VP9, so the
// default 75 is CRF 13 (x264) and 16 (VP9); 100 is CRF 0.
//
// Written durably (engine/io/seekable_output_file.h): the frames go to a hidden temporary file
// `.NAME.partial-PID` beside the destination, which only finish() renames into place after an
// fsync. A writer destroyed without finish() (an exception, a failed render) removes it, and a
// killed run's temporary is removed by the next writer to the same path or by
// remove_stale_staging of its folder: never a half-written video under the final name.
#include <cstdint>
#include <memory>
#include <string>

namespace pyro {

// What a VideoWriter for `path` would refuse before encoding anything: throws UserError naming
// `option` (a command's option, or empty) and the path for an extension other than .mp4, .webm
// or .gif, or when its folder does not exist. For commands that check their arguments first.
void check_video_path(const std::string& path, const std::string& option = "");

class VideoWriter {
 public:
  static constexpr int default_quality = 75;

  // Opens the encoder and the temporary file and writes the container's header. Throws
  // UserError for an extension other than .mp4, .webm, .gif (naming the path and those) or a
  // missing folder, IoError naming the file (the OS error or av_strerror's text) when libav or
  // the file system fails, std::invalid_argument for a size outside 1..16384, an fps outside
  // (0, 1000] or a quality outside 0..100.
  VideoWriter(const std::string& path, int width, int height, double fps,
              int quality = default_quality);
  ~VideoWriter();  // without finish(): removes the temporary file
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // One frame of width * height pixels, 8-bit sRGB, top row first: RGB (channels 3) or RGBA
  // (channels 4, alpha ignored: frames are opaque). Throws IoError when encoding or writing fails
  // (for a GIF, which only holds the frame here, when finish() encodes it).
  void add_frame(const uint8_t* pixels, int channels);
  // Flushes the encoder, writes the trailer, fsyncs and renames the file into place. Throws
  // IoError (then nothing is left under either name).
  void finish();

  int frames_added() const;
  // The temporary file the frames go to until finish().
  const std::string& temporary_path() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace pyro
