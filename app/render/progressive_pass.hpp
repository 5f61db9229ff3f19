#pragma once
// Progressive area-light sampling's sum and resolve, for Renderer::renderProgressive: the passes are
// added up in a float buffer (alpha counts them) over the depth the first pass wrote, one pass per
// call, in the order progressivePassOrder() gives; resolveInto() draws the mean so far, clamped and
// encoded as a one-pass frame (shaders/resolve.frag), into the target. The Renderer draws each pass's
// panes into sumTarget() with that pass's samples.
#include "core/scene/scene.hpp"
#include "render/gl_handles.hpp"
#include "render/image_pass.hpp"
#include "render/render_target.hpp"
#include "render/shader_library.hpp"

#include <glm/vec2.hpp>

#include <array>
#include <optional>
#include <vector>

namespace shadelab {

// The area-light samples one progressive pass evaluates: i = first.x + k stride.x, j = first.y + m stride.y.
struct AreaSamplePass {
    glm::ivec2 first{0};
    glm::ivec2 stride{1};
};

// How far the sum is: after passCount passes the image is a one-pass frame's, within float rounding.
struct ProgressiveStatus {
    int passesDone = 0;
    int passCount = 1;
    bool complete() const { return passesDone >= passCount; }
};

class ProgressivePass {
public:
    // Sizes the sum for width x height and starts it again when `restart`, the size or the stride
    // changed. `stride` is clamped per axis to the largest sample count of `scene`'s area lights
    // there: a larger one would leave passes without samples.
    void prepare(const Scene& scene, int width, int height, int stride, bool restart);
    // The next pass to draw into sumTarget(); none once the sum is complete.
    std::optional<AreaSamplePass> nextPass() const;
    // The first pass draws the sum's surfaces and depth; the later ones add to it.
    bool firstPass() const { return done_ == 0; }
    RenderTarget sumTarget() const { return {sumFbo_.get(), width_, height_}; }
    void passDrawn() { ++done_; }
    // Draws the mean so far into `target` (prepare()'s size), with the surfaces' depth for the overlays.
    // The resolve program is built on first use for each output encoding (ShaderError).
    void resolveInto(const Scene& scene, const RenderTarget& target, const ShaderLibrary& shaders);
    ProgressiveStatus status() const { return {done_, int(order_.size())}; }

private:
    GLuint resolveProgram(OutputEncoding encoding, const ShaderLibrary& shaders);

    gl::Framebuffer sumFbo_;
    gl::Texture sumColor_, depth_;  // RGBA32F, DEPTH24
    int width_ = 0, height_ = 0;
    glm::ivec2 stride_{0};
    std::vector<glm::ivec2> order_;  // each pass's first sample
    int done_ = 0;
    std::array<gl::Program, 2> resolve_;  // by output encoding (linear, sRGB)
    FullscreenTriangle fullscreen_;
};

// The order of progressive sampling's passes for `stride` (x, y): every first sample in
// [0, stride.x) x [0, stride.y) once, in ordered-dither (Bayer) order, so the passes drawn so far are
// spread over the light instead of filling it row by row.
std::vector<glm::ivec2> progressivePassOrder(const glm::ivec2& stride);

}  // namespace shadelab
