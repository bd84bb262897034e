#include "systems/flipbook_fire/flipbook_folder.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/png_file.h"
#include "systems/flipbook_fire/flipbook_atlas_folder.h"
#include "systems/flipbook_fire/flipbook_six_way_folder.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

// "frame_0012.png" -> prefix "frame_", number 12, digits 4; false when the stem ends in no digit.
struct NumberedName {
  std::string prefix;
  long long number = 0;
  std::string file;
};
bool split_number(const std::string& stem, NumberedName& out) {
  size_t i = stem.size();
  while (i > 0 && std::isdigit(static_cast<unsigned char>(stem[i - 1]))) --i;
  if (i == stem.size() || stem.size() - i > 12) return false;
  out.prefix = stem.substr(0, i);
  out.number = std::stoll(stem.substr(i));
  return true;
}

std::vector<uint8_t> to_rgba(const PngImage& img) {
  return flipbook_rgba(img.pixels.data(), img.width, img.height, img.channels);
}

// The folder's PNG files (any case of .png), sorted by name; UserError when there is no folder,
// it cannot be listed or it holds no PNG.
std::vector<std::string> list_png_files(const std::string& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw UserError(folder, "", "expected a folder of PNG flame frames, found no folder");
  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    if (!e.is_regular_file(ec)) continue;
    std::string ext = e.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".png") files.push_back(e.path().string());
  }
  if (ec) throw UserError(folder, "", "cannot list the folder: " + ec.message());
  if (files.empty())
    throw UserError(folder, "", "expected PNG flame frames (e.g. frame_0000.png, ...), found none");
  std::sort(files.begin(), files.end());
  return files;
}

// When every name ends in a number: refuses gaps (a missing frame would be a jump in the flame's
// motion) and mixed prefixes, and puts the files in number order (frame_10 after frame_9 even
// without leading zeros). Names without numbers keep their name order.
void order_numbered_frames(const std::string& folder, std::vector<std::string>& files) {
  std::vector<NumberedName> numbered(files.size());
  bool all_numbered = true;
  for (size_t i = 0; i < files.size(); ++i) {
    all_numbered = all_numbered && split_number(fs::path(files[i]).stem().string(), numbered[i]);
    numbered[i].file = fs::path(files[i]).filename().string();
  }
  if (!all_numbered) return;
  std::stable_sort(numbered.begin(), numbered.end(), [](const NumberedName& a, const NumberedName& b) {
    return a.prefix != b.prefix ? a.prefix < b.prefix : a.number < b.number;
  });
  for (size_t i = 1; i < numbered.size(); ++i) {
    if (numbered[i].prefix == numbered[i - 1].prefix &&
        numbered[i].number != numbered[i - 1].number + 1) {
      throw UserError(folder, "frame " + std::to_string(numbered[i - 1].number + 1),
                      "expected consecutively numbered frames, found none numbered " +
                          std::to_string(numbered[i - 1].number + 1) + " between " +
                          numbered[i - 1].file + " and " + numbered[i].file);
    }
    if (numbered[i].prefix != numbered[i - 1].prefix)
      throw UserError(folder, "", "expected frames with one name prefix, found \"" +
                                      numbered[0].prefix + "\" and \"" + numbered[i].prefix + "\"");
  }
  std::sort(files.begin(), files.end(), [](const std::string& a, const std::string& b) {
    NumberedName x, y;
    split_number(fs::path(a).stem().string(), x);
    split_number(fs::path(b).stem().string(), y);
    return x.number < y.number;
  });
}

// An optional flipbook.json in the folder states the frame count: it must match `frames`.
void check_manifest(const std::string& folder, size_t frames) {
  const fs::path manifest = fs::path(folder) / "flipbook.json";
  std::error_code ec;
  if (!fs::is_regular_file(manifest, ec)) return;
  nlohmann::json m;
  try {
    m = nlohmann::json::parse(read_text_file(manifest.string()));
  } catch (const nlohmann::json::exception& e) {
    throw UserError(manifest.string(), "", std::string("expected a JSON manifest: ") + e.what());
  }
  if (!m.is_object() || !m.contains("frames") || !m["frames"].is_number_unsigned())
    throw UserError(manifest.string(), "/frames", "expected the frame count, a non-negative integer");
  const auto expected = m["frames"].get<uint64_t>();
  if (expected != frames)
    throw UserError(manifest.string(), "/frames",
                    "expected " + std::to_string(expected) + " frames in the folder, found " +
                        std::to_string(frames));
}

// Reads every file of `f.files` into `f.rgba`, all of the first frame's size.
void read_frames(FlipbookFrames& f) {
  for (const std::string& file : f.files) {
    const PngImage img = read_png(file);  // UserError naming the file when unreadable
    if (f.rgba.empty()) {
      f.width = img.width;
      f.height = img.height;
    } else if (img.width != f.width || img.height != f.height) {
      throw UserError(file, "", "expected a frame of " + std::to_string(f.width) + "x" +
                                    std::to_string(f.height) + " pixels like " +
                                    fs::path(f.files[0]).filename().string() + ", found " +
                                    std::to_string(img.width) + "x" + std::to_string(img.height));
    }
    f.rgba.push_back(to_rgba(img));
  }
}

}  // namespace

std::vector<uint8_t> flipbook_rgba(const uint8_t* pixels, int width, int height, int channels) {
  const size_t n = static_cast<size_t>(width) * height;
  std::vector<uint8_t> out(n * 4);
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = &pixels[i * static_cast<size_t>(channels)];
    uint8_t r, g, b, a;
    switch (channels) {
      case 1: r = g = b = a = p[0]; break;
      case 2: r = g = b = p[0]; a = p[1]; break;
      case 3: r = p[0]; g = p[1]; b = p[2]; a = std::max({r, g, b}); break;
      default: r = p[0]; g = p[1]; b = p[2]; a = p[3]; break;
    }
    out[i * 4 + 0] = r;
    out[i * 4 + 1] = g;
    out[i * 4 + 2] = b;
    out[i * 4 + 3] = a;
  }
  return out;
}

FlipbookFrames read_flipbook_folder(const std::string& folder) {
  if (holds_flipbook_atlas(folder)) return read_flipbook_atlas(folder);
  if (holds_six_way_bake(folder)) return read_six_way_flipbook(folder);
  FlipbookFrames f;
  f.folder = folder;
  f.files = list_png_files(folder);
  order_numbered_frames(folder, f.files);
  check_manifest(folder, f.files.size());
  read_frames(f);
  return f;
}

namespace {

// Motion in the cropped frame's UV: u scales by full width / cropped width, v likewise.
void crop_motion(std::vector<MotionField>& motion, int x0, int y0, int w, int h) {
  for (MotionField& m : motion) {
    const float su = static_cast<float>(m.width) / static_cast<float>(w);
    const float sv = static_cast<float>(m.height) / static_cast<float>(h);
    MotionField out;
    out.width = w;
    out.height = h;
    out.uv.resize(static_cast<size_t>(w) * h * 2);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = (static_cast<size_t>(y) * w + x) * 2;
        out.uv[i] = m.u(x0 + x, y0 + y) * su;
        out.uv[i + 1] = m.v(x0 + x, y0 + y) * sv;
      }
    m = std::move(out);
  }
}

struct FrameCrop {
  int full_width, x0, y0, w, h;
};

// The crop of an RGBA frame, channels from `first_faded` on scaled by their row's `keep`.
void crop_and_fade(std::vector<uint8_t>& frame, const FrameCrop& c, const std::vector<float>& keep,
                   int first_faded) {
  std::vector<uint8_t> out(static_cast<size_t>(c.w) * c.h * 4);
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x)
      for (int ch = 0; ch < 4; ++ch) {
        const uint8_t v = frame[(static_cast<size_t>(c.y0 + y) * c.full_width + (c.x0 + x)) * 4 + ch];
        const float k = ch >= first_faded ? keep[static_cast<size_t>(y)] : 1.0f;
        out[(static_cast<size_t>(y) * c.w + x) * 4 + ch] = static_cast<uint8_t>(std::lround(v * k));
      }
  frame = std::move(out);
}

}  // namespace

float base_softening(float a, float base_line, float soften) {
  if (a < base_line) return 0.0f;
  if (a < base_line + soften) return (a - base_line) / soften;
  return 1.0f;
}

void prepare_flipbook(FlipbookFrames& frames, const FlipbookPreparation& p) {
  const glm::vec4 c = p.crop;
  for (int i = 0; i < 4; ++i)
    if (!(c[i] >= 0.0f && c[i] <= 1.0f)) throw std::invalid_argument("prepare_flipbook: crop outside [0, 1]");
  const int x0 = static_cast<int>(std::lround(c.x * frames.width));
  const int y0 = static_cast<int>(std::lround(c.y * frames.height));
  const int x1 = static_cast<int>(std::lround(c.z * frames.width));
  const int y1 = static_cast<int>(std::lround(c.w * frames.height));
  if (x1 <= x0 || y1 <= y0) throw std::invalid_argument("prepare_flipbook: empty crop");
  const int w = x1 - x0, h = y1 - y0;
  std::vector<float> keep(static_cast<size_t>(h));
  for (int y = 0; y < h; ++y)
    keep[static_cast<size_t>(y)] =
        base_softening((static_cast<float>(h - y) - 0.5f) / static_cast<float>(h), p.base_line, p.soften);
  const FrameCrop crop{frames.width, x0, y0, w, h};
  // A six-way flipbook's lightmaps are lighting: only its alpha (channel 3 of A) fades.
  for (std::vector<uint8_t>& frame : frames.rgba) crop_and_fade(frame, crop, keep, frames.six_way() ? 3 : 0);
  for (std::vector<uint8_t>& frame : frames.six_way_b) crop_and_fade(frame, crop, keep, 4);
  crop_motion(frames.motion, x0, y0, w, h);
  frames.width = w;
  frames.height = h;
}

}  // namespace pyro
