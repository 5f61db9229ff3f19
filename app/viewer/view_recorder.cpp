#include "viewer/view_recorder.hpp"

#include "core/base/error.hpp"
#include "platform/platform.hpp"

#if SHADELAB_HAVE_VIDEO
#include "video/video_encoder.hpp"
#endif

#include <cmath>
#include <filesystem>
#include <system_error>

namespace shadelab {

#if SHADELAB_HAVE_VIDEO
struct ViewRecorder::Encoder {
    VideoEncoder video;
};
#else
struct ViewRecorder::Encoder {};
#endif

ViewRecorder::ViewRecorder(const std::string& path, int width, int height, int fps)
    : path_(path), width_(width), height_(height), fps_(fps) {
#if SHADELAB_HAVE_VIDEO
    const std::filesystem::path target(path);
    const std::string name =
        ".shadelab-recording-" + std::to_string(platform::processId()) + "-" + target.filename().string();
    temporary_ = (target.parent_path() / name).string();
    VideoSettings settings;
    settings.fps = fps;
    encoder_.reset(new Encoder{VideoEncoder(temporary_, VideoFormat::Mp4, width, height, settings, path)});
#else
    throw InputError(
        "recording needs video encoding: this shadelab was built without it (CMake option SHADELAB_VIDEO)");
#endif
}

ViewRecorder::~ViewRecorder() {
    if (encoder_) {
        encoder_.reset();
        std::error_code ignored;
        std::filesystem::remove(temporary_, ignored);
    }
}

void ViewRecorder::add(const Image& frame, double seconds) {
#if SHADELAB_HAVE_VIDEO
    if (!encoder_) return;
    // The video's frames up to this time show this image (at least one: the first frame is never lost).
    const long until = std::max(frames_ + (frames_ == 0 ? 1 : 0), long(std::floor(seconds * fps_)) + 1);
    for (; frames_ < until; ++frames_) encoder_->video.addFrame(frame);
#else
    (void)frame, (void)seconds, (void)fps_, (void)frames_;  // never reached: the constructor threw
#endif
}

void ViewRecorder::stop() {
#if SHADELAB_HAVE_VIDEO
    if (!encoder_) return;
    try {
        encoder_->video.finish();
        encoder_.reset();
        std::filesystem::rename(temporary_, path_);
    } catch (...) {
        encoder_.reset();
        std::error_code ignored;
        std::filesystem::remove(temporary_, ignored);
        throw;
    }
#endif
}

}  // namespace shadelab
