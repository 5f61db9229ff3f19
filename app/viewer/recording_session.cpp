#include "viewer/recording_session.hpp"

#include "core/scene/animation.hpp"

namespace shadelab {

void RecordingSession::frame(const Image& view, Clock::time_point now) {
    if (recorder_ && (toggled_ || view.width != recorder_->width() || view.height != recorder_->height())) {
        const bool resized = !toggled_;
        toggled_ = false;
        const std::string said = stopAndSay();
        if (resized) say_(said + " (recording stopped: the view changed size)", false);
        return;
    }
    if (toggled_) {
        toggled_ = false;
        if (view.width <= 0 || view.height <= 0) return say_("nothing to record: the view is empty", true);
        const std::string path = newPath_();
        try {
            recorder_ = std::make_unique<ViewRecorder>(path, view.width, view.height, kDefaultVideoFps);
            start_ = now;
            say_("recording " + path + " (Ctrl+R stops)", false);
        } catch (const std::exception& e) {
            return say_(std::string("recording failed: ") + e.what(), true);
        }
    }
    if (!recorder_) return;
    try {
        recorder_->add(view, std::chrono::duration<double>(now - start_).count());
    } catch (const std::exception& e) {
        recorder_.reset();  // removes what it wrote
        say_(std::string("recording failed: ") + e.what(), true);
    }
}

void RecordingSession::stop() {
    if (recorder_) stopAndSay();
}

// Stops the running recording; returns what it said.
std::string RecordingSession::stopAndSay() {
    const std::string path = recorder_->path();
    std::string said;
    try {
        recorder_->stop();
        lastSaved_ = path;
        said = "saved recording " + path;
        say_(said, false);
    } catch (const std::exception& e) {
        said = std::string("recording failed: ") + e.what();
        say_(said, true);
    }
    recorder_.reset();
    return said;
}

}  // namespace shadelab
