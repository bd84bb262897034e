#include "systems/output/png_sink.h"

#include "engine/io/png_file.h"
#include "systems/output/frame_names.h"

namespace pyro {

namespace {

// Columns x0 .. x0 + width - 1 of the RGBA image, as RGB.
std::vector<uint8_t> rgb_columns(const ShownImage& image, int x0, int width) {
  const int w = image.width, h = image.height;
  std::vector<uint8_t> rgb(static_cast<size_t>(width) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        rgb[(static_cast<size_t>(y) * width + x) * 3 + c] =
            image.rgba[(static_cast<size_t>(y) * w + x0 + x) * 4 + c];
  return rgb;
}

}  // namespace

std::vector<std::string> write_shown_png(const ShownImage& shown, const std::string& stem,
                                         bool two_views) {
  const int w = shown.width, h = shown.height;
  if (!two_views) {
    write_png(stem + ".png", w, h, 3, rgb_columns(shown, 0, w));
    return {stem + ".png"};
  }
  const int half = w / 2;
  write_png(stem + "_left.png", half, h, 3, rgb_columns(shown, 0, half));
  write_png(stem + "_right.png", half, h, 3, rgb_columns(shown, half, half));
  return {stem + "_left.png", stem + "_right.png"};
}

std::vector<std::string> PngSink::files(int index) const {
  std::vector<std::string> names;
  for (const std::string& stem : frame_view_stems(index, two_views_)) names.push_back(stem + ".png");
  return names;
}

void PngSink::write(OutputFrame& frame, const std::filesystem::path& staging) {
  write_shown_png(frame.shown(), (staging / frame_stem(frame.index())).string(), two_views_);
}

}  // namespace pyro
