#include "engine/io/exr_file.h"

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfPixelType.h>
#include <half.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <stdexcept>

#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"

namespace pyro {

namespace {

// OpenEXR's output stream over memory: the file is encoded into bytes, which are then written
// durably, every write checked. The bytes are complete only once the Imf::OutputFile is
// destroyed: its destructor seeks back and writes the line-offset table (where each block of
// rows starts), which until then holds zeros.
class MemoryStream : public Imf::OStream {
 public:
  explicit MemoryStream(const std::string& name) : Imf::OStream(name.c_str()) {}
  void write(const char c[], int n) override {
    const size_t end = position_ + static_cast<size_t>(n);
    if (end > bytes_.size()) bytes_.resize(end);
    std::memcpy(bytes_.data() + position_, c, static_cast<size_t>(n));
    position_ = end;
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override { position_ = static_cast<size_t>(pos); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
  size_t position_ = 0;
};

void check_sizes(const ExrImage& image) {
  if (image.width <= 0 || image.height <= 0)
    throw std::invalid_argument("write_exr: the image has no pixels");
  const size_t pixels = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  if (image.rgba.size() != pixels * 4)
    throw std::invalid_argument("write_exr: RGBA value count does not match the size");
  if (!image.depth.empty() && image.depth.size() != pixels)
    throw std::invalid_argument("write_exr: depth value count does not match the size");
}

std::string encode_exr(const std::string& path, const ExrImage& image) {
  Imf::Header header(image.width, image.height);
  // ZIP (zlib over blocks of 16 rows): lossless, decodes fast, and deflates FLOAT depth as well
  // as HALF colour; PIZ's wavelet is made for HALF data and gains mainly on grainy photographs.
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const char* name : {"R", "G", "B", "A"}) header.channels().insert(name, Imf::Channel(Imf::HALF));
  const bool has_depth = !image.depth.empty();
  if (has_depth) header.channels().insert("Z", Imf::Channel(Imf::FLOAT));

  std::vector<half> rgba(image.rgba.begin(), image.rgba.end());
  const size_t row = static_cast<size_t>(image.width);
  Imf::FrameBuffer frame;
  const char* names[4] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c)
    frame.insert(names[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(rgba.data() + c),
                                      4 * sizeof(half), 4 * sizeof(half) * row));
  if (has_depth)
    frame.insert("Z", Imf::Slice(Imf::FLOAT,
                                 reinterpret_cast<char*>(const_cast<float*>(image.depth.data())),
                                 sizeof(float), sizeof(float) * row));
  MemoryStream stream(path);
  {
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
  }  // closed: OpenEXR seeks back and writes the line-offset table as the file is destroyed
  return stream.bytes();
}

}  // namespace

void write_exr(const std::string& path, const ExrImage& image) {
  check_sizes(image);
  std::string encoded;
  try {
    encoded = encode_exr(path, image);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": the OpenEXR encoder failed: " + e.what());
  }
  write_file_durably(path, encoded);
}

namespace {

ExrImage decode_exr(const std::string& path) {
  Imf::InputFile file(path.c_str());
  const Imath::Box2i window = file.header().dataWindow();
  ExrImage image;
  image.width = window.max.x - window.min.x + 1;
  image.height = window.max.y - window.min.y + 1;
  const int64_t pixels = int64_t{image.width} * image.height;
  if (image.width <= 0 || image.height <= 0 || pixels > (int64_t{1} << 28))
    throw UserError(path, "", "an OpenEXR image of 1 to 2^28 pixels");
  image.rgba.resize(static_cast<size_t>(pixels) * 4);
  Imf::FrameBuffer frame;
  const char* names[4] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c)
    frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, image.rgba.data() + c, window,
                                            4 * sizeof(float), 4 * sizeof(float) * image.width,
                                            1, 1, c == 3 ? 1.0 : 0.0));
  if (file.header().channels().findChannel("Z")) {
    image.depth.resize(static_cast<size_t>(pixels));
    frame.insert("Z", Imf::Slice::Make(Imf::FLOAT, image.depth.data(), window, sizeof(float),
                                       sizeof(float) * image.width));
  }
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  return image;
}

}  // namespace

ExrImage read_exr(const std::string& path) {
  try {
    return decode_exr(path);
  } catch (const UserError&) {
    throw;
  } catch (const std::exception& e) {
    throw UserError(path, "", std::string("a readable OpenEXR file: ") + e.what());
  }
}

}  // namespace pyro
