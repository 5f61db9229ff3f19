#pragma once
// Ctrl+R / the record button: recording the view as shown to an MP4 (ViewRecorder). A toggle takes
// effect at the frame's end, once the view is drawn: the first frame recorded is the one the key was
// pressed in. The video has the view's size when it started: a resize stops (and saves) it. What
// happens is said through `say` (the viewer's status line). GL-free.
#include "core/image/image.hpp"
#include "viewer/view_recorder.hpp"

#include <chrono>
#include <functional>
#include <memory>
#include <string>

namespace shadelab {

class RecordingSession {
public:
    using Clock = std::chrono::steady_clock;
    using Say = std::function<void(const std::string& message, bool isError)>;

    // `newPath` names each new video (the viewer: a timestamped .mp4 in the working directory).
    RecordingSession(std::function<std::string()> newPath, Say say)
        : newPath_(std::move(newPath)), say_(std::move(say)) {}

    void toggle() { toggled_ = true; }
    bool active() const { return recorder_ != nullptr; }
    // This frame's view is read back for the recording (one runs or starts now).
    bool capturing() const { return recorder_ || toggled_; }
    // The last video saved (empty: none yet).
    const std::string& lastSaved() const { return lastSaved_; }

    // At the frame's end, with the view as drawn (empty when it was not): starts or stops when toggled,
    // adds the frame while recording, at its time since the start.
    void frame(const Image& view, Clock::time_point now);
    // Stops and saves (quitting while recording keeps the video).
    void stop();

private:
    std::string stopAndSay();
    std::function<std::string()> newPath_;
    Say say_;
    std::unique_ptr<ViewRecorder> recorder_;
    bool toggled_ = false;
    Clock::time_point start_;
    std::string lastSaved_;
};

}  // namespace shadelab
