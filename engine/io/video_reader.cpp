#include "engine/io/video_reader.h"

#include <filesystem>
#include <memory>

#include "engine/core/user_error.h"
#include "engine/io/libav_error.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

namespace pyro {

namespace {

struct VideoDecoding {
  std::string path;
  AVFormatContext* demuxer = nullptr;
  AVCodecContext* decoder = nullptr;
  SwsContext* scaler = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  int stream = -1;
  VideoClip clip;

  ~VideoDecoding() {
    sws_freeContext(scaler);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&decoder);
    avformat_close_input(&demuxer);
  }
  void check(int result, const std::string& action) const {
    if (result < 0) throw UserError(path, "", "a video file libav can " + action + ": " + libav_error_text(result));
  }
  void open();
  void keep(const AVFrame& decoded);
  void drain();
};

void VideoDecoding::open() {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw UserError(path, "", "a video file, found " +
                                  std::string(std::filesystem::exists(path, ec) ? "no regular file"
                                                                                : "no file"));
  // "file:" keeps a ':' in the path from being read as a protocol name.
  check(avformat_open_input(&demuxer, ("file:" + path).c_str(), nullptr, nullptr), "open");
  check(avformat_find_stream_info(demuxer, nullptr), "read");
  const AVCodec* codec = nullptr;
  stream = av_find_best_stream(demuxer, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
  check(stream, "find a video stream in");
  decoder = avcodec_alloc_context3(codec);
  frame = av_frame_alloc();
  packet = av_packet_alloc();
  if (!decoder || !frame || !packet) check(AVERROR(ENOMEM), "allocate a decoder for");
  const AVStream* video = demuxer->streams[stream];
  check(avcodec_parameters_to_context(decoder, video->codecpar), "decode");
  check(avcodec_open2(decoder, codec, nullptr), "decode");
  const AVRational rate = video->avg_frame_rate.num > 0 ? video->avg_frame_rate : video->r_frame_rate;
  clip.fps = rate.den > 0 ? av_q2d(rate) : 0.0;
  clip.width = decoder->width;
  clip.height = decoder->height;
}

// Converts a decoded frame to RGB24 with the matrix and range it is tagged with.
void VideoDecoding::keep(const AVFrame& decoded) {
  const auto format = static_cast<AVPixelFormat>(decoded.format);
  scaler = sws_getCachedContext(scaler, decoded.width, decoded.height, format, decoded.width,
                                decoded.height, AV_PIX_FMT_RGB24,
                                SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT,
                                nullptr, nullptr, nullptr);
  if (!scaler) check(AVERROR(EINVAL), "convert to RGB");
  const int matrix = decoded.colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT;
  sws_setColorspaceDetails(scaler, sws_getCoefficients(matrix),
                           decoded.color_range == AVCOL_RANGE_JPEG ? 1 : 0,
                           sws_getCoefficients(SWS_CS_DEFAULT), 1, 0, 1 << 16, 1 << 16);
  std::vector<uint8_t> rgb(static_cast<size_t>(decoded.width) * decoded.height * 3);
  uint8_t* out[1] = {rgb.data()};
  const int stride[1] = {decoded.width * 3};
  sws_scale(scaler, decoded.data, decoded.linesize, 0, decoded.height, out, stride);
  clip.frames.push_back(std::move(rgb));
}

// Takes every frame the decoder has ready.
void VideoDecoding::drain() {
  for (;;) {
    const int received = avcodec_receive_frame(decoder, frame);
    if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
    check(received, "decode");
    keep(*frame);
    av_frame_unref(frame);
  }
}

}  // namespace

VideoClip read_video(const std::string& path) {
  VideoDecoding d;
  d.path = path;
  d.open();
  int read = 0;
  while ((read = av_read_frame(d.demuxer, d.packet)) >= 0) {
    const int sent = d.packet->stream_index == d.stream ? avcodec_send_packet(d.decoder, d.packet) : 0;
    av_packet_unref(d.packet);
    d.check(sent, "decode");
    d.drain();
  }
  if (read != AVERROR_EOF) d.check(read, "read");
  d.check(avcodec_send_packet(d.decoder, nullptr), "decode");
  d.drain();
  return std::move(d.clip);
}

}  // namespace pyro
