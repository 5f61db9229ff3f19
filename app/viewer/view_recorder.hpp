#pragma once
// Recording the 3D view to a video (Ctrl+R, the File section's record button): the frames as shown, at
// the view's size, to an MP4 (video/video_encoder.hpp) that keeps real time. Needs SHADELAB_VIDEO; where
// it was not built, starting a recording throws InputError saying so.
#include "core/image/image.hpp"

#include <memory>
#include <string>

namespace shadelab {

class ViewRecorder {
public:
    // Starts recording width x height frames to `path`, written under a temporary name beside it
    // (".shadelab-recording-…") until stop() renames it. Throws InputError.
    ViewRecorder(const std::string& path, int width, int height, int fps);
    ~ViewRecorder();  // a recording that was not stopped is removed
    ViewRecorder(const ViewRecorder&) = delete;
    ViewRecorder& operator=(const ViewRecorder&) = delete;

    // Adds the frame shown `seconds` after the start; repeated (or skipped) so that each of the video's
    // frames shows what was on screen at its time: a slow frame lasts as long as it was shown.
    void add(const Image& frame, double seconds);
    // Finishes the video and renames it to path(). Throws InputError; the temporary is removed either way.
    void stop();

    const std::string& path() const { return path_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    struct Encoder;
    std::string path_, temporary_;
    int width_, height_, fps_;
    long frames_ = 0;
    std::unique_ptr<Encoder> encoder_;
};

}  // namespace shadelab
