#include "systems/output/png_sink.h"

#include "engine/io/png_file.h"
#include "systems/output/frame_names.h"
#include "systems/output/transparent_frame.h"

namespace pyro {

namespace {

// Columns x0 .. x0 + width - 1 of the RGBA image, as RGB (`channels` 3) or RGBA (4).
std::vector<uint8_t> columns(const ShownImage& image, int x0, int width, int channels) {
  const int w = image.width, h = image.height;
  std::vector<uint8_t> out(static_cast<size_t>(width) * h * channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c)
        out[(static_cast<size_t>(y) * width + x) * channels + c] =
            image.rgba[(static_cast<size_t>(y) * w + x0 + x) * 4 + c];
  return out;
}

}  // namespace

std::vector<std::string> write_shown_png(const ShownImage& shown, const std::string& stem,
                                         bool two_views, int channels) {
  const int w = shown.width, h = shown.height;
  if (!two_views) {
    write_png(stem + ".png", w, h, channels, columns(shown, 0, w, channels));
    return {stem + ".png"};
  }
  const int half = w / 2;
  write_png(stem + "_left.png", half, h, channels, columns(shown, 0, half, channels));
  write_png(stem + "_right.png", half, h, channels, columns(shown, half, half, channels));
  return {stem + "_left.png", stem + "_right.png"};
}

std::vector<std::string> PngSink::files(int index) const {
  std::vector<std::string> names;
  for (const std::string& stem : frame_view_stems(index, two_views_)) names.push_back(stem + ".png");
  return names;
}

void PngSink::write(OutputFrame& frame, const std::filesystem::path& staging) {
  const std::string stem = (staging / frame_stem(frame.index())).string();
  if (const std::optional<FrameBackground>& background = frame.background())
    write_shown_png(straight_alpha_image(frame.shown(), background->shown), stem, two_views_, 4);
  else
    write_shown_png(frame.shown(), stem, two_views_);
}

}  // namespace pyro
