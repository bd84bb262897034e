#pragma once
// A farm's PNG frames encoded into one video (engine/io/video_file.h) once they are all there:
// the frames are read back from the output folder in frame order.
#include <string>
#include <vector>

namespace pyro {

// Encodes `files` (PNG frame files in `dir`, in frame order, one per frame) into `video` at
// `fps`. Throws UserError naming --video when a file is not a PNG (EXR frames hold linear
// values a video cannot show as such; stereo frames in two files are two pictures) or when the
// frames differ in size, IoError when encoding or writing fails (no video is left then).
void encode_frames_video(const std::string& dir, const std::vector<std::string>& files,
                         const std::string& video, double fps, int quality);

}  // namespace pyro
