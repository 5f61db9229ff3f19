#pragma once
// How each frame's 3D view is drawn: anti-aliased (MSAA) where it pays, and on a software rasterizer
// smaller while it moves. On a GPU every frame is anti-aliased; on a software
// rasterizer (4x costs several times a frame on llvmpipe) only a still view, a captured one and the
// last; while the view is dragged, a slider held or an animation plays, the scene is drawn into a
// framebuffer movingScale() of the view's size per axis and magnified into it, the scale following the
// moving frames' own time (aiming at 30 FPS); a still view is drawn at full size and anti-aliased
// again, one more frame after the movement stops. GL-free: the targets are the viewer's.
namespace shadelab {

class ViewQuality {
public:
    // The moving frames' own time aimed at (30 FPS while a lecturer drags), and the smallest share of
    // the view's size per axis they may be drawn at.
    static constexpr double kMovingBudgetMs = 30.0;
    static constexpr float kMinMovingScale = 0.25f;

    ViewQuality(int msaaSamples, bool softwareGl) : samples_(msaaSamples), softwareGl_(softwareGl) {}

    int msaaSamples() const { return samples_; }
    void setMsaaSamples(int samples) { samples_ = samples; }  // the panel's setting, from the next frame
    bool softwareGl() const { return softwareGl_; }

    struct Frame {
        bool still = false;      // no event since the last frame
        bool mouseDown = false;  // a button held (a drag, a slider)
        bool playing = false;    // an animation plays
        bool capture = false;    // the view is read back (a screenshot, a recording, a file)
        bool last = false;       // the session's last frame
        bool scripted = false;   // --frames: every frame as the headless image, never reduced
        double lastFrameMs = 0;  // the last frame's own time
    };
    // Before the view is drawn: decides this frame's anti-aliasing and size.
    void plan(const Frame& frame);
    // After: the view is anti-aliased now if it was drawn so at full size.
    void drawn() { antiAliased_ = antiAliasThisFrame_ && !reducedThisFrame_; }

    bool antiAliasThisFrame() const { return antiAliasThisFrame_; }
    bool reducedThisFrame() const { return reducedThisFrame_; }
    // A moving frame on a software rasterizer (reduced or not): the renderer takes fewer shadow samples
    // (one lookup per light, one sample per area light) and a still view takes them all again.
    bool movingThisFrame() const { return movingLastFrame_; }
    float movingScale() const { return movingScale_; }
    // The view is not yet as a still one should be: one more frame draws it anti-aliased at full size.
    bool wantsStillFrame() const { return (samples_ > 1 && !antiAliased_) || reducedThisFrame_; }

private:
    int samples_ = 1;
    bool softwareGl_ = false;
    bool antiAliased_ = false, antiAliasThisFrame_ = false;
    float movingScale_ = 1.0f;
    bool movingLastFrame_ = false, reducedThisFrame_ = false;
};

}  // namespace shadelab
