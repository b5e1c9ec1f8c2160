// VideoWriter over libavformat / libavcodec / libswscale (or, in a build
// without them, a writer that refuses with a clear message).
#include "foveate/bench/video.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "foveate/core/error.hpp"

#if FOVEATE_HAVE_FFMPEG
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libswscale/swscale.h>
}
#endif

namespace foveate::bench {

namespace fs = std::filesystem;

#if FOVEATE_HAVE_FFMPEG

namespace {

std::string av_error(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, buf, sizeof buf);
  return buf;
}

struct CodecContextFree {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct FrameFree {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct PacketFree {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct SwsFree {
  void operator()(SwsContext* s) const { sws_freeContext(s); }
};
struct FormatFree {
  void operator()(AVFormatContext* f) const {
    if (f->pb) avio_closep(&f->pb);
    avformat_free_context(f);
  }
};
struct DictFree {
  void operator()(AVDictionary* d) const { av_dict_free(&d); }
};

// Encoders in order of preference: H.264 first, then what every libavcodec has.
constexpr const char* kEncoders[] = {"libx264", "libopenh264", "mpeg4"};

}  // namespace

struct VideoWriter::Impl {
  std::string path, tmp, encoder;
  int width = 0, height = 0;       // the frames'
  int padded_w = 0, padded_h = 0;  // what is encoded (even)
  int frames = 0;
  bool finished = false;
  std::unique_ptr<AVFormatContext, FormatFree> format;
  std::unique_ptr<AVCodecContext, CodecContextFree> codec;
  AVStream* stream = nullptr;  // owned by format
  std::unique_ptr<AVFrame, FrameFree> frame;
  std::unique_ptr<AVPacket, PacketFree> packet;
  std::unique_ptr<SwsContext, SwsFree> sws;
  std::vector<std::uint8_t> padded;  // RGBA at the padded size

  ~Impl() {
    if (finished) return;
    format.reset();  // closes the file
    std::error_code ec;
    if (!tmp.empty()) fs::remove(tmp, ec);
  }

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw Error(path + ": " + what + (code < 0 ? ": " + av_error(code) : ""));
  }

  // Sends `f` (nullptr: flush) and writes every packet the encoder returns.
  void encode(const AVFrame* f) {
    int rc = avcodec_send_frame(codec.get(), f);
    if (rc < 0) fail("encoding failed", rc);
    for (;;) {
      rc = avcodec_receive_packet(codec.get(), packet.get());
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
      if (rc < 0) fail("encoding failed", rc);
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(format.get(), packet.get());
      if (rc < 0) fail("write failed", rc);
    }
  }

  void open_encoder(AVRational fps, const std::vector<std::string>& names) {
    std::string tried;
    for (const std::string& n : names) {
      const char* name = n.c_str();
      const AVCodec* c = avcodec_find_encoder_by_name(name);
      if (!c || avformat_query_codec(format->oformat, c->id, FF_COMPLIANCE_NORMAL) != 1) {
        tried += (tried.empty() ? "" : ", ") + n + (c ? " (not for this container)" : " (absent)");
        continue;
      }
      std::unique_ptr<AVCodecContext, CodecContextFree> ctx(avcodec_alloc_context3(c));
      if (!ctx) throw std::bad_alloc();
      ctx->width = padded_w;
      ctx->height = padded_h;
      ctx->pix_fmt = AV_PIX_FMT_YUV420P;
      ctx->time_base = av_inv_q(fps);
      ctx->framerate = fps;
      ctx->gop_size = 30;
      // sRGB values through the BT.601 matrix (swscale's default), limited range.
      ctx->colorspace = AVCOL_SPC_SMPTE170M;
      ctx->color_range = AVCOL_RANGE_MPEG;
      ctx->color_primaries = AVCOL_PRI_BT709;
      ctx->color_trc = AVCOL_TRC_IEC61966_2_1;
      if (format->oformat->flags & AVFMT_GLOBALHEADER) ctx->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
      AVDictionary* raw = nullptr;
      if (std::strcmp(name, "libx264") == 0) {
        av_dict_set(&raw, "preset", "veryfast", 0);
        av_dict_set(&raw, "crf", "18", 0);
      } else if (std::strcmp(name, "mpeg4") == 0) {
        ctx->flags |= AV_CODEC_FLAG_QSCALE;
        ctx->global_quality = FF_QP2LAMBDA * 3;
      }
      std::unique_ptr<AVDictionary, DictFree> opts(raw);
      AVDictionary* o = opts.release();
      const int rc = avcodec_open2(ctx.get(), c, &o);
      opts.reset(o);
      if (rc < 0) {
        tried += std::string(tried.empty() ? "" : ", ") + name + " (" + av_error(rc) + ")";
        continue;
      }
      codec = std::move(ctx);
      encoder = name;
      return;
    }
    throw Error(path + ": no usable video encoder (tried " + tried + ")");
  }
};

VideoWriter::VideoWriter(const std::string& path, int width, int height, double fps,
                         const std::vector<std::string>& encoders)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = path;
  av_log_set_level(AV_LOG_ERROR);  // the encoder's statistics are not the user's business
  if (width < 1 || height < 1) throw Error(path + ": video size must be positive");
  if (!(fps > 0 && fps <= 1000)) throw Error(path + ": frame rate must be in (0, 1000]");
  m.width = width;
  m.height = height;
  m.padded_w = width + (width & 1);
  m.padded_h = height + (height & 1);

  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error(path + ": is a directory, not a video file");
  const AVOutputFormat* container = av_guess_format(nullptr, path.c_str(), nullptr);
  if (!container) {
    throw Error(path +
                ": cannot tell the video container from the file name (use .mp4, .mkv or .mov)");
  }
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) {
    fs::create_directories(parent, ec);
    if (ec)
      throw Error(path + ": cannot create the folder " + parent.string() + ": " + ec.message());
  }
  // The temporary file beside the final one (so the rename stays on one file system).
  std::string templ = path + ".tmp-XXXXXX";
  const int fd = ::mkstemp(templ.data());
  if (fd < 0) throw Error(path + ": cannot write: " + std::strerror(errno));
  // mkstemp makes the file private (0600); a video is an output like the
  // PNG files beside it, so it gets the mode a newly created file gets
  // (0666 less the umask, which can only be read by setting it).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  m.tmp = templ;

  AVFormatContext* fmt = nullptr;
  int rc = avformat_alloc_output_context2(&fmt, container, nullptr, m.tmp.c_str());
  if (rc < 0 || !fmt) m.fail("cannot set up the container", rc);
  m.format.reset(fmt);
  m.open_encoder(av_d2q(fps, 100000),
                 encoders.empty()
                     ? std::vector<std::string>(std::begin(kEncoders), std::end(kEncoders))
                     : encoders);

  m.stream = avformat_new_stream(fmt, nullptr);
  if (!m.stream) throw std::bad_alloc();
  rc = avcodec_parameters_from_context(m.stream->codecpar, m.codec.get());
  if (rc < 0) m.fail("cannot set up the stream", rc);
  m.stream->time_base = m.codec->time_base;
  m.stream->avg_frame_rate = m.codec->framerate;

  rc = avio_open(&fmt->pb, m.tmp.c_str(), AVIO_FLAG_WRITE);
  if (rc < 0) m.fail("cannot write", rc);
  AVDictionary* raw = nullptr;
  av_dict_set(&raw, "movflags", "+faststart", 0);  // playable while downloading (.mp4, .mov)
  rc = avformat_write_header(fmt, &raw);
  av_dict_free(&raw);
  if (rc < 0) m.fail("cannot write the header", rc);

  m.frame.reset(av_frame_alloc());
  m.packet.reset(av_packet_alloc());
  if (!m.frame || !m.packet) throw std::bad_alloc();
  m.frame->format = AV_PIX_FMT_YUV420P;
  m.frame->width = m.padded_w;
  m.frame->height = m.padded_h;
  rc = av_frame_get_buffer(m.frame.get(), 0);
  if (rc < 0) m.fail("cannot allocate a frame", rc);
  m.sws.reset(sws_getContext(m.padded_w, m.padded_h, AV_PIX_FMT_RGBA, m.padded_w, m.padded_h,
                             AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_ACCURATE_RND, nullptr, nullptr,
                             nullptr));
  if (!m.sws) throw Error(path + ": cannot set up the RGB to YUV conversion");
  m.padded.assign(static_cast<size_t>(m.padded_w) * m.padded_h * 4, 0);
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::write(const Image& image) {
  Impl& m = *impl_;
  if (m.finished) throw Error(m.path + ": the video is already finished");
  if (image.width != m.width || image.height != m.height) {
    throw Error(m.path + ": frame of " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + " in a video of " + std::to_string(m.width) + "x" +
                std::to_string(m.height));
  }
  // Copy into the padded buffer, repeating the last column and row.
  const size_t row = static_cast<size_t>(m.width) * 4;
  for (int y = 0; y < m.padded_h; ++y) {
    std::uint8_t* dst = &m.padded[static_cast<size_t>(y) * m.padded_w * 4];
    std::memcpy(dst, image.at(0, std::min(y, m.height - 1)), row);
    if (m.padded_w > m.width) std::memcpy(dst + row, dst + row - 4, 4);
  }
  int rc = av_frame_make_writable(m.frame.get());
  if (rc < 0) m.fail("cannot allocate a frame", rc);
  const std::uint8_t* src[1] = {m.padded.data()};
  const int stride[1] = {m.padded_w * 4};
  sws_scale(m.sws.get(), src, stride, 0, m.padded_h, m.frame->data, m.frame->linesize);
  m.frame->pts = m.frames++;
  m.encode(m.frame.get());
}

void VideoWriter::finish() {
  Impl& m = *impl_;
  if (m.finished) return;
  if (m.frames == 0) throw Error(m.path + ": no frames to write");
  m.encode(nullptr);
  int rc = av_write_trailer(m.format.get());
  if (rc < 0) m.fail("cannot write the trailer", rc);
  rc = avio_closep(&m.format->pb);
  if (rc < 0) m.fail("write failed", rc);
  std::error_code ec;
  fs::rename(m.tmp, m.path, ec);
  if (ec) throw Error(m.path + ": cannot move the finished video into place: " + ec.message());
  m.finished = true;
}

const std::string& VideoWriter::encoder() const { return impl_->encoder; }
int VideoWriter::padded_width() const { return impl_->padded_w; }
int VideoWriter::padded_height() const { return impl_->padded_h; }
int VideoWriter::frames() const { return impl_->frames; }
bool VideoWriter::padded() const {
  return impl_->padded_w != impl_->width || impl_->padded_h != impl_->height;
}
const std::string& VideoWriter::path() const { return impl_->path; }
bool VideoWriter::available() { return true; }

#else  // no libavcodec in this build

struct VideoWriter::Impl {
  std::string path, encoder;
};

VideoWriter::VideoWriter(const std::string& path, int, int, double,
                         const std::vector<std::string>&) {
  throw Error(path +
              ": this foveate was built without video support (install libavcodec-dev, "
              "libavformat-dev, libswscale-dev and libavutil-dev, then reconfigure and rebuild)");
}
VideoWriter::~VideoWriter() = default;
void VideoWriter::write(const Image&) {}
void VideoWriter::finish() {}
const std::string& VideoWriter::encoder() const { return impl_->encoder; }
int VideoWriter::padded_width() const { return 0; }
int VideoWriter::padded_height() const { return 0; }
int VideoWriter::frames() const { return 0; }
bool VideoWriter::padded() const { return false; }
const std::string& VideoWriter::path() const { return impl_->path; }
bool VideoWriter::available() { return false; }

#endif

}  // namespace foveate::bench
