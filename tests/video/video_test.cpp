// Videos (--animate --output FILE.gif|.mp4|.webm, app/video): each file is decoded here through
// libavformat and libavcodec (no ffprobe) and checked for its codec, size, frame count and frame rate,
// and its first and last frames against single-frame PNG renders of the ramp's end values. Small
// frames and few of them: these run in CI and again under the sanitizers.
#include "cli/run_shadelab.hpp"
#include "core/image/image.hpp"
#include "video/palette.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <array>
#include <set>

namespace fs = std::filesystem;
using namespace shadelab;

namespace {

struct Decoded {
    std::string codec;       // libavcodec's name: "h264", "vp9", "gif"
    int width = 0, height = 0;
    AVRational frameRate{0, 1};   // the stream's average frame rate
    int frames = 0;
    std::vector<double> times;    // each frame's time in seconds
    Image first, last;            // RGBA
};

// Every frame of the file's video stream, decoded and converted to RGBA.
Decoded decode(const std::string& path) {
    Decoded d;
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) {
        ADD_FAILURE() << path << ": libavformat cannot open it";
        return d;
    }
    avformat_find_stream_info(format, nullptr);
    const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    EXPECT_GE(index, 0) << path << ": no video stream";
    if (index < 0) return avformat_close_input(&format), d;
    AVStream* stream = format->streams[index];
    const AVCodec* decoder = avcodec_find_decoder(stream->codecpar->codec_id);
    AVCodecContext* codec = avcodec_alloc_context3(decoder);
    avcodec_parameters_to_context(codec, stream->codecpar);
    EXPECT_EQ(avcodec_open2(codec, decoder, nullptr), 0);
    d.codec = decoder->name;
    d.width = codec->width, d.height = codec->height;
    d.frameRate = stream->avg_frame_rate;
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    SwsContext* toRgba = nullptr;
    const auto drain = [&] {
        while (avcodec_receive_frame(codec, frame) == 0) {
            Image rgba(frame->width, frame->height);
            toRgba = sws_getCachedContext(toRgba, frame->width, frame->height, AVPixelFormat(frame->format), frame->width,
                                          frame->height, AV_PIX_FMT_RGBA, SWS_POINT, nullptr, nullptr, nullptr);
            if (frame->format != AV_PIX_FMT_PAL8)  // as the encoder wrote it: BT.709, limited range
                sws_setColorspaceDetails(toRgba, sws_getCoefficients(SWS_CS_ITU709), 0, sws_getCoefficients(SWS_CS_ITU709),
                                         1, 0, 1 << 16, 1 << 16);
            std::uint8_t* rows[1] = {rgba.rgba.data()};
            const int stride[1] = {4 * rgba.width};
            sws_scale(toRgba, frame->data, frame->linesize, 0, frame->height, rows, stride);
            if (d.frames == 0) d.first = rgba;
            d.last = std::move(rgba);
            d.times.push_back(double(frame->best_effort_timestamp) * av_q2d(stream->time_base));
            ++d.frames;
        }
    };
    while (av_read_frame(format, packet) >= 0) {
        if (packet->stream_index == index) avcodec_send_packet(codec, packet), drain();
        av_packet_unref(packet);
    }
    avcodec_send_packet(codec, nullptr);
    drain();
    sws_freeContext(toRgba);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
    return d;
}

// Per channel (R, G, B): the largest difference and the mean difference.
struct Difference {
    int max = 0;
    double mean = 0;
};
Difference difference(const Image& a, const Image& b) {
    Difference d;
    if (a.width != b.width || a.height != b.height) return {255, 255.0};
    double sum = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const int diff = std::abs(int(a.rgba[i]) - int(b.rgba[i]));
        d.max = std::max(d.max, diff);
        sum += diff;
    }
    d.mean = sum / double(a.rgba.size() / 4 * 3);
    return d;
}

// The top-level boxes of an MP4 file, in order ("ftyp", "moov", "mdat", ...).
std::vector<std::string> mp4Boxes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<std::string> boxes;
    for (unsigned char header[8]; in.read(reinterpret_cast<char*>(header), 8);) {
        const std::uint64_t size = std::uint64_t(header[0]) << 24 | header[1] << 16 | header[2] << 8 | header[3];
        boxes.emplace_back(reinterpret_cast<char*>(header + 4), 4);
        if (size < 8) break;
        in.seekg(std::streamoff(size - 8), std::ios::cur);
    }
    return boxes;
}

class Video : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "video" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    // shadelab `args` --output NAME, which must succeed.
    void render(std::vector<std::string> args, const std::string& name) const {
        args.insert(args.end(), {"--output", path(name)});
        const test::RunResult r = test::runShadelab(args, fs::current_path(), dir_);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        ASSERT_TRUE(r.err.empty()) << r.err;
    }
    // The ramp k_e 1 -> 1000 over 0.5 s at 20 fps (11 frames, the last at k_e 1000) into `name`, and the
    // single frames at k_e 1 and 1000 as PNGs.
    void rampAndEnds(const std::vector<std::string>& scene, const std::string& name) {
        std::vector<std::string> video = scene;
        video.insert(video.end(), {"--animate", "ke=1..1000:log:0.5", "--fps", "20"});
        render(video, name);
        std::vector<std::string> a = scene, b = scene;
        a.insert(a.end(), {"--ke", "1"});
        b.insert(b.end(), {"--ke", "1000"});
        render(a, "ke1.png");
        render(b, "ke1000.png");
        ke1_ = readPng(path("ke1.png"));
        ke1000_ = readPng(path("ke1000.png"));
    }
    void checkRamp(const std::string& name, const char* codec, double loss);
    fs::path dir_;
    Image ke1_, ke1000_;
};

const std::vector<std::string> kSmall = {"--size", "160x120"};  // the default scene: three panes
// Flat shading of an icosphere (80 faces): at most 81 colours a frame, so a correct palette is exact.
const std::vector<std::string> kFewColours = {"--size", "64x48", "--layout", "single", "--shading", "flat",
                                              "--mesh", "icosphere:1"};

}  // namespace

TEST(Palette, AFrameOfAtMost256ColoursIsKeptExactly) {
    Image img(40, 30);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            std::uint8_t* p = img.pixel(x, y);
            const int c = (x * 7 + y * 13) % 256;  // 256 colours
            p[0] = std::uint8_t(c), p[1] = std::uint8_t(255 - c), p[2] = std::uint8_t(c / 2), p[3] = 255;
        }
    for (bool dither : {false, true}) {
        const PalettedImage out = paletteFrame(img, dither);
        ASSERT_LE(out.palette.size(), 256u);
        for (int i = 0; i < img.width * img.height; ++i)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(out.palette[out.indices[std::size_t(i)]][std::size_t(c)], img.rgba[std::size_t(i) * 4 + std::size_t(c)])
                    << "pixel " << i << (dither ? " dithered" : "");
    }
}

// A highlight's shades: red rising to white over many pixels, 766 distinct colours, plus a large flat
// background that a pixel-weighted palette would spend its entries on. Median cut over the distinct
// colours keeps every pixel of the ramp within 3 levels (of 255) of its colour: 256 entries for 766
// shades, about 3 shades an entry; a band would be a jump of many levels.
TEST(Palette, AHighlightRampDoesNotBand) {
    Image img(1000, 200);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            std::uint8_t* p = img.pixel(x, y);
            p[3] = 255;
            if (y < 150) {
                p[0] = 20, p[1] = 20, p[2] = 24;  // background
                continue;
            }
            const int v = std::min(x, 765);  // 0..765: red, then green and blue up to white
            p[0] = std::uint8_t(std::min(v, 255)), p[1] = std::uint8_t(std::clamp(v - 255, 0, 255));
            p[2] = std::uint8_t(std::clamp(v - 510, 0, 255));
        }
    const PalettedImage out = paletteFrame(img, false);
    EXPECT_GE(out.palette.size(), 250u);  // 256 boxes, a few with the same mean
    int worst = 0;
    std::set<int> used;
    for (int x = 0; x < img.width; ++x) {
        const std::size_t i = std::size_t(199 * img.width + x);
        used.insert(out.indices[i]);
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(int(out.palette[out.indices[i]][std::size_t(c)]) - int(img.rgba[i * 4 + std::size_t(c)])));
    }
    EXPECT_LE(worst, 3);
    EXPECT_GE(used.size(), 250u);  // the ramp gets nearly every entry
    const std::set<std::array<std::uint8_t, 3>> distinct(out.palette.begin(), out.palette.end());
    EXPECT_EQ(distinct.size(), out.palette.size()) << "an entry repeated (FFmpeg's GIF encoder maps it to entry 0)";
}

TEST_F(Video, GifFramesAreTheSingleFrameRendersExactly) {
    rampAndEnds(kFewColours, "ramp.gif");
    const Decoded d = decode(path("ramp.gif"));
    EXPECT_EQ(d.codec, "gif");
    EXPECT_EQ(d.width, 64);
    EXPECT_EQ(d.height, 48);
    EXPECT_EQ(d.frames, 11);
    ASSERT_EQ(d.times.size(), 11u);
    for (std::size_t i = 1; i < d.times.size(); ++i) EXPECT_NEAR(d.times[i] - d.times[i - 1], 0.05, 1e-9) << i;  // 20 fps
    const Difference first = difference(d.first, ke1_), last = difference(d.last, ke1000_);
    EXPECT_EQ(first.max, 0);
    EXPECT_EQ(last.max, 0);
    EXPECT_GT(difference(ke1_, ke1000_).max, 40);  // the two ends do differ: the check above could fail
}

// The ramp's video at 160x120 decoded: `codec`, 11 frames, its first and last frames the PNGs of k_e 1
// and 1000 within `loss` (mean per channel, of 255), and its last frame clearly not k_e 1's.
void Video::checkRamp(const std::string& name, const char* codec, double loss) {
    rampAndEnds(kSmall, name);
    const Decoded d = decode(path(name));
    EXPECT_EQ(d.codec, codec);
    EXPECT_EQ(d.width, 160);
    EXPECT_EQ(d.height, 120);
    EXPECT_EQ(d.frames, 11);
    ASSERT_EQ(d.times.size(), 11u);
    EXPECT_NEAR(d.times.back() - d.times.front(), 0.5, 1e-3);  // 20 fps (WebM keeps milliseconds)
    const Difference first = difference(d.first, ke1_), last = difference(d.last, ke1000_);
    EXPECT_LT(first.mean, loss) << "max " << first.max;
    EXPECT_LT(last.mean, loss) << "max " << last.max;
    EXPECT_GT(difference(d.last, ke1_).mean, 6.0);  // the last frame is k_e 1000's, not the first's
    if (std::string(codec) == "h264") {
        EXPECT_EQ(d.frameRate.num, d.frameRate.den * 20) << d.frameRate.num << "/" << d.frameRate.den;
        const std::vector<std::string> boxes = mp4Boxes(path(name));
        const auto at = [&](const char* box) { return std::find(boxes.begin(), boxes.end(), box) - boxes.begin(); };
        EXPECT_LT(at("moov"), at("mdat")) << "faststart: the index before the media data";
    }
}

// A frame of more than 256 colours (the default scene's three panes) gets 256 of them: every pixel
// stays close to the render. Measured: max 4 and 1, mean 0.12 and 0.0015 at the two ends. (A repeated
// palette entry, which FFmpeg 5.1's encoder draws in entry 0's colour, gave max 151 in a 480x160 GIF
// of this ramp; the palette test above checks that entries are distinct.)
TEST_F(Video, GifOfManyColoursStaysCloseToTheRenders) {
    rampAndEnds(kSmall, "ramp.gif");
    const Decoded d = decode(path("ramp.gif"));
    EXPECT_EQ(d.frames, 11);
    const Difference first = difference(d.first, ke1_), last = difference(d.last, ke1000_);
    EXPECT_LE(first.max, 8) << first.mean;
    EXPECT_LE(last.max, 8) << last.mean;
}

// The codec's loss, measured (x264 veryfast, CRF 18, yuv420p, 160x120): mean 1.42 and 1.29 per channel
// (of 255) at the two ends, max 53 and 54 at the panes' edges and the highlight, where 2x2 pixels share
// one chroma sample. The other end of the ramp is mean 12.1 away.
TEST_F(Video, Mp4IsH264WithItsIndexFirstAndFramesWithinTheCodecsLoss) { checkRamp("ramp.mp4", "h264", 2.5); }

// Measured (libvpx-vp9 CRF 30, cpu-used 6, 160x120): mean 1.26 and 1.41, max 51 and 70; the other end 12.2.
TEST_F(Video, WebmIsVp9WithFramesWithinTheCodecsLoss) { checkRamp("ramp.webm", "vp9", 2.5); }

TEST_F(Video, Mp4OfAnOddSizeLosesTheLastColumnAndRow) {
    render({"--size", "65x49", "--animate", "camera-orbit:0.2", "--fps", "10"}, "odd.mp4");
    const Decoded d = decode(path("odd.mp4"));
    EXPECT_EQ(d.width, 64);
    EXPECT_EQ(d.height, 48);
    EXPECT_EQ(d.frames, 2);  // an orbit alone: t = 0 and 0.1, not 0.2 (the first frame again)
}
