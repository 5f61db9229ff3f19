#pragma once
// Videos for slides and course pages, encoded in-process by Debian's FFmpeg libraries (libavcodec,
// libavformat, libswscale; no ffmpeg process): frames go in one at a time and are encoded at once, so
// memory does not grow with their number.
//   .mp4   H.264 (libx264), yuv420p, BT.709, the index ("moov") at the front ("faststart"): plays in
//          browsers and PowerPoint. yuv420p needs an even width and height: an odd one loses its
//          last column or row.
//   .webm  VP9 (libvpx-vp9), yuv420p, BT.709 (odd sizes are fine).
//   .gif   libavcodec's GIF encoder on 8-bit frames, each with its own palette (video/palette.hpp),
//          looping forever; frame delays are in 1/100 s, so 30 fps plays as close to it as that allows.
// Part of the build where the libraries are found (CMake option SHADELAB_VIDEO).
#include "core/image/image.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace shadelab {

enum class VideoFormat { Gif, Mp4, WebM };
// From the file name's extension (any case); nullopt for any other.
std::optional<VideoFormat> videoFormatOf(const std::string& path);

struct VideoSettings {
    int fps = 30;
    bool dither = false;  // GIF: Floyd-Steinberg onto each frame's palette
    // H.264: x264's preset and constant-quality factor (bench/README.md, "Videos", for why these).
    const char* x264Preset = "veryfast";
    int x264Crf = 18;
    // VP9: libvpx's constant quality (0..63, lower is better) and speed (0..8, higher is faster).
    int vp9Crf = 30;
    int vp9CpuUsed = 6;
};

class VideoEncoder {
public:
    // Opens `file` (written as it goes) for frames of width x height. Throws InputError for a codec
    // this FFmpeg lacks or a file it cannot write, naming `shownAs` (default: `file`).
    VideoEncoder(const std::string& file, VideoFormat format, int width, int height, const VideoSettings& settings,
                 const std::string& shownAs = "");
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // Encodes one frame of the size given to the constructor (alpha is ignored).
    void addFrame(const Image& frame);
    // Flushes the encoder and writes the file's index. Call once, after the last frame.
    void finish();

private:
    struct State;
    std::unique_ptr<State> state_;
};

// Writes the video `path` atomically (core/base/file_io.hpp): `frames` gets an encoder on a temporary
// file beside `path` and adds every frame; when it returns, the video is finished and renamed over `path`.
// If it throws, no file is left.
void writeVideo(const std::string& path, int width, int height, const VideoSettings& settings,
                const std::function<void(VideoEncoder&)>& frames);

}  // namespace shadelab
