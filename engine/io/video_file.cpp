#include "engine/io/video_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "engine/core/user_error.h"
#include "engine/io/io_error.h"
#include "engine/io/libav_error.h"
#include "engine/io/palette_quantizer.h"
#include "engine/io/seekable_output_file.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libswscale/swscale.h>
}

namespace pyro {

namespace {

struct VideoFormat {
  const char* muxer;
  const char* encoder;
  AVPixelFormat pixels;
  int max_crf;     // 0: the encoder has no quality setting (GIF)
  bool even_size;  // 4:2:0 H.264 needs even widths and heights
};

VideoFormat format_for(const std::string& path, const std::string& option = "") {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".mp4") return {"mp4", "libx264", AV_PIX_FMT_YUV420P, 51, true};
  if (extension == ".webm") return {"webm", "libvpx-vp9", AV_PIX_FMT_YUV420P, 63, false};
  if (extension == ".gif") return {"gif", "gif", AV_PIX_FMT_PAL8, 0, false};
  throw UserError(path, option, "a video file name ending in .mp4, .webm or .gif, found '" +
                                extension + "'");
}

void check_video_size(int width, int height, double fps, int quality) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument("VideoWriter: width and height must be in 1..16384");
  if (!(fps > 0.0 && fps <= 1000.0))
    throw std::invalid_argument("VideoWriter: fps must be in (0, 1000]");
  if (quality < 0 || quality > 100)
    throw std::invalid_argument("VideoWriter: quality must be in 0..100");
}

int write_callback(void* opaque, uint8_t* bytes, int size) {
  const int error = static_cast<SeekableOutputFile*>(opaque)->write(bytes, static_cast<size_t>(size));
  return error ? AVERROR(error) : size;
}

int64_t seek_callback(void* opaque, int64_t offset, int whence) {
  if (whence & AVSEEK_SIZE) return AVERROR(ENOSYS);
  const int64_t at = static_cast<SeekableOutputFile*>(opaque)->seek(offset, whence & ~AVSEEK_FORCE);
  return at < 0 ? AVERROR(-at) : at;
}

}  // namespace

struct VideoWriter::State {
  std::string path;
  VideoFormat format;
  SeekableOutputFile file;
  int width, height;                // the frames'
  int coded_width, coded_height;    // the video's (even for H.264)
  AVFormatContext* muxer = nullptr;
  AVIOContext* io = nullptr;
  AVCodecContext* encoder = nullptr;
  AVStream* stream = nullptr;
  SwsContext* scaler = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  std::vector<uint8_t> rgb;  // one frame as RGB24 at the coded size
  std::vector<std::vector<uint8_t>> held;  // GIF: every frame's rgb, until finish()
  int frames = 0;
  bool finished = false;

  State(const std::string& p, int w, int h)
      : path(p), format(format_for(p)), file(p), width(w), height(h),
        coded_width(format.even_size ? (w + 1) / 2 * 2 : w),
        coded_height(format.even_size ? (h + 1) / 2 * 2 : h) {}
  ~State();

  // Throws for a negative libav result: the file's own errno first (a write the OS refused).
  void check(int result, const std::string& action) const {
    if (result >= 0) return;
    if (file.first_error()) throw IoError(path, "write the video", file.first_error());
    throw_libav_io_error(path, action, result);
  }
  void open_muxer();
  void open_encoder(AVRational rate, int quality);
  void open_converter();
  void open_scaler();
  void fill_rgb(const uint8_t* pixels, int channels);
  void encode(const AVFrame* input);
  void encode_rgb();
  void encode_held_gif();
};

VideoWriter::State::~State() {
  sws_freeContext(scaler);
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&encoder);
  if (muxer) muxer->pb = nullptr;
  avformat_free_context(muxer);
  if (io) av_freep(&io->buffer);
  avio_context_free(&io);
}

void VideoWriter::State::open_muxer() {
  check(avformat_alloc_output_context2(&muxer, nullptr, format.muxer, nullptr),
        "set up the video container");
  constexpr int buffer_size = 1 << 16;
  auto* buffer = static_cast<unsigned char*>(av_malloc(buffer_size));
  if (!buffer) throw IoError(path, "allocate the video's output buffer", ENOMEM);
  io = avio_alloc_context(buffer, buffer_size, 1, &file, nullptr, write_callback, seek_callback);
  if (!io) {
    av_free(buffer);
    throw IoError(path, "allocate the video's output", ENOMEM);
  }
  muxer->pb = io;
  muxer->flags |= AVFMT_FLAG_CUSTOM_IO;
}

void VideoWriter::State::open_encoder(AVRational rate, int quality) {
  const AVCodec* codec = avcodec_find_encoder_by_name(format.encoder);
  if (!codec)
    throw IoError(path, std::string("find the ") + format.encoder + " encoder in this libavcodec",
                  ENOSYS);
  encoder = avcodec_alloc_context3(codec);
  if (!encoder) throw IoError(path, "allocate the video encoder", ENOMEM);
  encoder->width = coded_width;
  encoder->height = coded_height;
  encoder->pix_fmt = format.pixels;
  encoder->time_base = av_inv_q(rate);
  encoder->framerate = rate;
  if (muxer->oformat->flags & AVFMT_GLOBALHEADER) encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* options = nullptr;
  if (format.max_crf > 0) {
    encoder->bit_rate = 0;  // constant quality: the CRF alone decides (VP9 needs b = 0 for it)
    encoder->colorspace = AVCOL_SPC_BT709;
    encoder->color_primaries = AVCOL_PRI_BT709;
    encoder->color_trc = AVCOL_TRC_IEC61966_2_1;  // the frames are sRGB-encoded
    encoder->color_range = AVCOL_RANGE_MPEG;
    const int crf = static_cast<int>(std::lround(format.max_crf * (100 - quality) / 100.0));
    av_dict_set_int(&options, "crf", crf, 0);
    if (codec->id == AV_CODEC_ID_VP9) {
      av_dict_set(&options, "deadline", "good", 0);
      av_dict_set(&options, "cpu-used", "4", 0);  // libvpx's speed steps: 4 is fast at good quality
      av_dict_set(&options, "row-mt", "1", 0);
    }
  }
  const int opened = avcodec_open2(encoder, codec, &options);
  av_dict_free(&options);
  check(opened, std::string("open the ") + format.encoder + " encoder");
  stream = avformat_new_stream(muxer, nullptr);
  if (!stream) throw IoError(path, "add the video stream", ENOMEM);
  check(avcodec_parameters_from_context(stream->codecpar, encoder), "set up the video stream");
  stream->time_base = encoder->time_base;
  stream->avg_frame_rate = rate;
  stream->r_frame_rate = rate;
}

// SWS_FULL_CHR_H_INP filters every column into the subsampled chroma (by default swscale takes
// every other one, which aliases at coloured edges). GIF frames need no converter: their
// palette indices are found here (encode_held_gif).
void VideoWriter::State::open_converter() {
  if (format.pixels != AV_PIX_FMT_PAL8) open_scaler();
  frame = av_frame_alloc();
  packet = av_packet_alloc();
  if (!frame || !packet) throw IoError(path, "allocate a video frame", ENOMEM);
  frame->format = format.pixels;
  frame->width = coded_width;
  frame->height = coded_height;
  check(av_frame_get_buffer(frame, 0), "allocate a video frame");
  rgb.resize(static_cast<size_t>(coded_width) * coded_height * 3);
}

void VideoWriter::State::open_scaler() {
  scaler = sws_getContext(coded_width, coded_height, AV_PIX_FMT_RGB24, coded_width, coded_height,
                          format.pixels, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP,
                          nullptr, nullptr, nullptr);
  if (!scaler) throw IoError(path, "set up the colour conversion", EINVAL);
  if (format.max_crf > 0)  // sRGB in full range to BT.709 YUV in limited range
    sws_setColorspaceDetails(scaler, sws_getCoefficients(SWS_CS_ITU709), 1,
                             sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16, 1 << 16);
}

// The frame as RGB24 at the coded size: alpha dropped, an odd edge repeated into the padding.
void VideoWriter::State::fill_rgb(const uint8_t* pixels, int channels) {
  for (int y = 0; y < coded_height; ++y) {
    const uint8_t* row = pixels + static_cast<size_t>(std::min(y, height - 1)) * width * channels;
    uint8_t* out = rgb.data() + static_cast<size_t>(y) * coded_width * 3;
    for (int x = 0; x < coded_width; ++x) {
      const uint8_t* p = row + static_cast<size_t>(std::min(x, width - 1)) * channels;
      std::memcpy(out + static_cast<size_t>(x) * 3, p, 3);
    }
  }
}

// Sends `input` (nullptr: the end) and writes every packet the encoder has ready.
void VideoWriter::State::encode(const AVFrame* input) {
  check(avcodec_send_frame(encoder, input), "encode a video frame");
  for (;;) {
    const int received = avcodec_receive_packet(encoder, packet);
    if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
    check(received, "encode a video frame");
    av_packet_rescale_ts(packet, encoder->time_base, stream->time_base);
    packet->stream_index = stream->index;
    check(av_interleaved_write_frame(muxer, packet), "write the video");
  }
}

void check_video_path(const std::string& path, const std::string& option) {
  format_for(path, option);
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec))
    throw UserError(path, option, "an existing folder to write the video into, found none");
}

VideoWriter::VideoWriter(const std::string& path, int width, int height, double fps, int quality) {
  check_video_size(width, height, fps, quality);
  // The encoders' per-run statistics stay quiet unless the program asked libav for them.
  if (av_log_get_level() == AV_LOG_INFO) av_log_set_level(AV_LOG_ERROR);
  state_ = std::make_unique<State>(path, width, height);
  State& s = *state_;
  s.open_muxer();
  s.open_encoder(av_d2q(fps, 100000), quality);
  s.open_converter();
  s.check(avformat_write_header(s.muxer, nullptr), "write the video's header");
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::add_frame(const uint8_t* pixels, int channels) {
  State& s = *state_;
  if (s.finished) throw std::logic_error("VideoWriter::add_frame after finish()");
  if (channels != 3 && channels != 4)
    throw std::invalid_argument("VideoWriter::add_frame: channels must be 3 or 4");
  s.fill_rgb(pixels, channels);
  if (s.format.pixels == AV_PIX_FMT_PAL8) {
    s.held.push_back(s.rgb);  // encoded by finish(), with the palette of every frame
    s.frames++;
    return;
  }
  s.encode_rgb();
}

// The frame in `rgb`, converted and sent to the encoder.
void VideoWriter::State::encode_rgb() {
  check(av_frame_make_writable(frame), "allocate a video frame");
  const uint8_t* source[1] = {rgb.data()};
  const int stride[1] = {coded_width * 3};
  sws_scale(scaler, source, stride, 0, coded_height, frame->data, frame->linesize);
  frame->pts = frames++;
  encode(frame);
}

// GIF: one palette of 256 colours made from the pixels of every held frame
// (engine/io/palette_quantizer.h), each frame's pixels mapped to their nearest palette colour.
// One palette for the whole clip: the encoder writes it once, as the global colour table, and
// may leave pixels whose index did not change out of a frame.
void VideoWriter::State::encode_held_gif() {
  PaletteBuilder builder;
  for (const std::vector<uint8_t>& f : held) builder.add_pixels(f.data(), f.size() / 3);
  std::vector<PaletteColor> colors = builder.palette(256);
  PaletteMapper mapper(colors);
  colors.resize(256, colors.back());
  for (size_t f = 0; f < held.size(); ++f) {
    check(av_frame_make_writable(frame), "allocate a video frame");
    auto* table = reinterpret_cast<uint32_t*>(frame->data[1]);
    for (size_t i = 0; i < 256; ++i)  // AV_PIX_FMT_PAL8: native-endian 0xAARRGGBB, opaque
      table[i] = 0xff000000u | uint32_t(colors[i][0]) << 16 | uint32_t(colors[i][1]) << 8 | colors[i][2];
    for (int y = 0; y < coded_height; ++y)
      mapper.map(held[f].data() + static_cast<size_t>(y) * coded_width * 3,
                 static_cast<size_t>(coded_width), frame->data[0] + static_cast<ptrdiff_t>(y) * frame->linesize[0]);
    frame->pts = static_cast<int64_t>(f);
    std::vector<uint8_t>().swap(held[f]);
    encode(frame);
  }
  held.clear();
}

void VideoWriter::finish() {
  State& s = *state_;
  if (s.finished) return;
  if (!s.held.empty()) s.encode_held_gif();
  s.encode(nullptr);
  s.check(av_write_trailer(s.muxer), "write the video's trailer");
  avio_flush(s.io);
  s.check(s.io->error, "write the video");
  s.file.commit();
  s.finished = true;
}

int VideoWriter::frames_added() const { return state_->frames; }

const std::string& VideoWriter::temporary_path() const { return state_->file.temporary(); }

}  // namespace pyro
