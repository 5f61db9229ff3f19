#include "video/video_encoder.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "video/palette.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <cstring>
#include <stdexcept>

namespace shadelab {
namespace {

std::string errorText(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

// A libav call's result: negative is an error, reported with `what`.
int check(int result, const std::string& what) {
    if (result < 0) throw std::runtime_error(what + ": " + errorText(result));
    return result;
}

const char* muxerName(VideoFormat f) { return f == VideoFormat::Gif ? "gif" : f == VideoFormat::Mp4 ? "mp4" : "webm"; }

const AVCodec* findEncoder(VideoFormat f, const std::string& file) {
    const char* name = f == VideoFormat::Gif ? "gif" : f == VideoFormat::Mp4 ? "libx264" : "libvpx-vp9";
    const AVCodec* codec = avcodec_find_encoder_by_name(name);
    if (!codec) throw InputError(file + ": this FFmpeg (libavcodec) has no " + name + " encoder");
    return codec;
}

}  // namespace

std::optional<VideoFormat> videoFormatOf(const std::string& path) {
    if (hasExtension(path, ".gif")) return VideoFormat::Gif;
    if (hasExtension(path, ".mp4")) return VideoFormat::Mp4;
    if (hasExtension(path, ".webm")) return VideoFormat::WebM;
    return std::nullopt;
}

struct VideoEncoder::State {
    VideoFormat format = VideoFormat::Mp4;
    VideoSettings settings;
    std::string file;
    int width = 0, height = 0;  // of the frames given; the encoded ones may be one less (MP4, odd sizes)
    AVFormatContext* muxer = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    SwsContext* toYuv = nullptr;
    std::int64_t pts = 0;
    bool finished = false;

    ~State() {
        sws_freeContext(toYuv);
        av_packet_free(&packet);
        av_frame_free(&frame);
        avcodec_free_context(&codec);
        if (muxer && muxer->pb) avio_closep(&muxer->pb);
        avformat_free_context(muxer);
    }

    void openCodec(const AVCodec* encoder, int encodedWidth, int encodedHeight);
    // Sends `f` (null: the end) to the encoder and writes every packet it has ready.
    void encode(const AVFrame* f);
};

void VideoEncoder::State::openCodec(const AVCodec* encoder, int encodedWidth, int encodedHeight) {
    codec = avcodec_alloc_context3(encoder);
    if (!codec) throw std::bad_alloc();
    codec->width = encodedWidth;
    codec->height = encodedHeight;
    codec->time_base = AVRational{1, settings.fps};
    codec->framerate = AVRational{settings.fps, 1};
    codec->thread_count = 0;  // as many as the machine has
    if (format == VideoFormat::Gif) {
        codec->pix_fmt = AV_PIX_FMT_PAL8;
    } else {
        codec->pix_fmt = AV_PIX_FMT_YUV420P;
        codec->colorspace = AVCOL_SPC_BT709;
        codec->color_primaries = AVCOL_PRI_BT709;
        codec->color_trc = AVCOL_TRC_BT709;
        codec->color_range = AVCOL_RANGE_MPEG;
        codec->gop_size = 2 * settings.fps;  // a key frame every 2 s: seeking in a slide's video
    }
    if (format == VideoFormat::Mp4) {
        av_opt_set(codec->priv_data, "preset", settings.x264Preset, 0);
        av_opt_set_int(codec->priv_data, "crf", settings.x264Crf, 0);
    } else if (format == VideoFormat::WebM) {
        codec->bit_rate = 0;  // constant quality
        av_opt_set_int(codec->priv_data, "crf", settings.vp9Crf, 0);
        av_opt_set_int(codec->priv_data, "cpu-used", settings.vp9CpuUsed, 0);
        av_opt_set(codec->priv_data, "deadline", "good", 0);
        av_opt_set_int(codec->priv_data, "row-mt", 1, 0);
    }
    if (muxer->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    check(avcodec_open2(codec, encoder, nullptr), file + ": cannot open the " + encoder->name + " encoder");
}

void VideoEncoder::State::encode(const AVFrame* f) {
    check(avcodec_send_frame(codec, f), file + ": encoding");
    for (;;) {
        const int got = avcodec_receive_packet(codec, packet);
        if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
        check(got, file + ": encoding");
        av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
        packet->stream_index = stream->index;
        const int written = av_interleaved_write_frame(muxer, packet);  // takes the packet's data
        if (written < 0) throw InputError(file + ": cannot write: " + errorText(written));
    }
}

VideoEncoder::VideoEncoder(const std::string& file, VideoFormat format, int width, int height,
                           const VideoSettings& settings, const std::string& shownAs)
    : state_(std::make_unique<State>()) {
    av_log_set_level(AV_LOG_QUIET);  // what goes wrong is thrown, and said in one line (main.cpp)
    State& s = *state_;
    s.format = format;
    s.settings = settings;
    s.width = width;
    s.height = height;
    s.file = shownAs.empty() ? file : shownAs;  // what messages call it
    const AVCodec* encoder = findEncoder(format, s.file);
    check(avformat_alloc_output_context2(&s.muxer, nullptr, muxerName(format), file.c_str()), s.file);
    // H.264 in yuv420p has chroma per 2x2 pixels: an odd side loses its last pixel (README, "Videos").
    const bool even = format == VideoFormat::Mp4;
    const int ew = even && width > 1 ? width & ~1 : width, eh = even && height > 1 ? height & ~1 : height;
    s.openCodec(encoder, ew, eh);
    s.stream = avformat_new_stream(s.muxer, nullptr);
    if (!s.stream) throw std::bad_alloc();
    check(avcodec_parameters_from_context(s.stream->codecpar, s.codec), s.file);
    s.stream->time_base = s.codec->time_base;
    s.stream->avg_frame_rate = s.codec->framerate;
    const int opened = avio_open(&s.muxer->pb, file.c_str(), AVIO_FLAG_WRITE);
    if (opened < 0) throw InputError(s.file + ": cannot write: " + errorText(opened));
    AVDictionary* options = nullptr;
    if (format == VideoFormat::Mp4) av_dict_set(&options, "movflags", "+faststart", 0);  // the index first
    const int header = avformat_write_header(s.muxer, &options);
    av_dict_free(&options);
    check(header, s.file + ": cannot start the " + std::string(muxerName(format)) + " file");
    s.frame = av_frame_alloc();
    s.packet = av_packet_alloc();
    if (!s.frame || !s.packet) throw std::bad_alloc();
    s.frame->format = s.codec->pix_fmt;
    s.frame->width = ew;
    s.frame->height = eh;
    check(av_frame_get_buffer(s.frame, 0), s.file);
    if (format != VideoFormat::Gif) {
        s.toYuv = sws_getContext(ew, eh, AV_PIX_FMT_RGBA, ew, eh, AV_PIX_FMT_YUV420P, SWS_BILINEAR, nullptr, nullptr,
                                 nullptr);
        if (!s.toYuv) throw std::runtime_error(s.file + ": no RGBA to yuv420p conversion");
        // Full-range RGB in, BT.709 limited-range YUV out, as the stream says.
        sws_setColorspaceDetails(s.toYuv, sws_getCoefficients(SWS_CS_ITU709), 1, sws_getCoefficients(SWS_CS_ITU709), 0,
                                 0, 1 << 16, 1 << 16);
    }
}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::addFrame(const Image& image) {
    State& s = *state_;
    if (image.width != s.width || image.height != s.height)
        throw std::logic_error("VideoEncoder::addFrame: the frame's size differs from the video's");
    check(av_frame_make_writable(s.frame), s.file);
    if (s.format == VideoFormat::Gif) {
        const PalettedImage paletted = paletteFrame(image, s.settings.dither);
        for (int y = 0; y < image.height; ++y)
            std::memcpy(s.frame->data[0] + std::ptrdiff_t(y) * s.frame->linesize[0],
                        &paletted.indices[std::size_t(y) * std::size_t(image.width)], std::size_t(image.width));
        // AVPALETTE: 256 x 0xAARRGGBB. The entries past the frame's repeat its last one; no pixel uses them.
        auto* palette = reinterpret_cast<std::uint32_t*>(s.frame->data[1]);
        for (std::size_t i = 0; i < 256; ++i) {
            const auto& c = i < paletted.palette.size() ? paletted.palette[i] : paletted.palette.back();
            palette[i] = 0xFF000000u | std::uint32_t(c[0]) << 16 | std::uint32_t(c[1]) << 8 | std::uint32_t(c[2]);
        }
    } else {
        const std::uint8_t* rows[1] = {image.rgba.data()};
        const int stride[1] = {4 * image.width};
        sws_scale(s.toYuv, rows, stride, 0, s.frame->height, s.frame->data, s.frame->linesize);
    }
    s.frame->pts = s.pts++;
    s.encode(s.frame);
}

void VideoEncoder::finish() {
    State& s = *state_;
    if (s.finished) return;
    s.finished = true;
    s.encode(nullptr);
    const int trailer = av_write_trailer(s.muxer);
    if (trailer < 0) throw InputError(s.file + ": cannot write: " + errorText(trailer));
    const int closed = avio_closep(&s.muxer->pb);
    if (closed < 0) throw InputError(s.file + ": cannot write: " + errorText(closed));
}

void writeVideo(const std::string& path, int width, int height, const VideoSettings& settings,
                const std::function<void(VideoEncoder&)>& frames) {
    const std::optional<VideoFormat> format = videoFormatOf(path);
    if (!format) throw InputError(path + ": not a video file name (.gif, .mp4, .webm)");
    writeFileAtomicByName(path, [&](const std::string& temporary) {
        VideoEncoder encoder(temporary, *format, width, height, settings, path);
        frames(encoder);
        encoder.finish();
        return true;
    });
}

}  // namespace shadelab
