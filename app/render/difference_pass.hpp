#pragma once
// The difference pane of layout diff (A | B | |A - B| x factor), drawn after the scene's panes: panes A
// and B are copied out of the target (blits, so a multisampled target is resolved on the way) and
// shaders/difference.frag draws |A - B| x factor from the copies into the third pane. Owns the two
// copies, their framebuffers and the program.
#include "core/geometry/camera.hpp"
#include "render/gl_handles.hpp"
#include "render/image_pass.hpp"
#include "render/render_target.hpp"
#include "render/shader_library.hpp"

#include <array>
#include <vector>

namespace shadelab {

class DifferencePass {
public:
    // Draws the difference pane of `panes` (layoutPanes(): A, B, then the difference) into `target`,
    // which holds A and B already; a layout without one draws nothing. The program is built on first
    // use (ShaderError).
    void draw(const std::vector<Pane>& panes, float factor, const RenderTarget& target, const ShaderLibrary& shaders);

private:
    void makeProgram(const ShaderLibrary& shaders);
    void resizeSources(int width, int height);  // (re)creates the copies when their size changed
    void copySources(const Pane& a, const Pane& b, const RenderTarget& target);

    std::array<gl::Texture, 2> sources_;  // A and B, the difference pane's size (RGBA8)
    std::array<gl::Framebuffer, 2> sourceFbos_;
    int width_ = 0, height_ = 0;
#if SHADELAB_GLES
    // ES 3.0 resolves a multisampled framebuffer only into a rectangle of the same place and size: a
    // multisampled target is resolved whole into this copy first, and the panes are copied out of it.
    gl::Texture resolved_;
    gl::Framebuffer resolvedFbo_;
    int resolvedWidth_ = 0, resolvedHeight_ = 0;
#endif
    gl::Program program_;
    FullscreenTriangle fullscreen_;
};

}  // namespace shadelab
