#include "render/difference_pass.hpp"

#include "render/multisample_target.hpp"
#include "render/program.hpp"

namespace shadelab {

void DifferencePass::draw(const std::vector<Pane>& panes, float factor, const RenderTarget& target,
                          const ShaderLibrary& shaders) {
    if (panes.size() != 3 || !panes[2].difference) return;
    const Pane& pane = panes[2];
    if (pane.width <= 0 || pane.height <= 0) return;
    if (!program_) makeProgram(shaders);
    resizeSources(pane.width, pane.height);
    copySources(panes[0], panes[1], target);
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    const int originY = target.height - pane.y - pane.height;
    glViewport(pane.x, originY, pane.width, pane.height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(program_.get());
    glUniform2i(glGetUniformLocation(program_.get(), "u_paneOrigin"), pane.x, originY);
    glUniform1f(glGetUniformLocation(program_.get(), "u_factor"), factor);
    fullscreen_.draw(program_.get());
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_DEPTH_TEST);
}

void DifferencePass::makeProgram(const ShaderLibrary& shaders) {
    program_ = buildProgram("difference", shaders, {}, kFullscreenVertex);
    glUseProgram(program_.get());
    glUniform1i(glGetUniformLocation(program_.get(), "u_sourceA"), 0);
    glUniform1i(glGetUniformLocation(program_.get(), "u_sourceB"), 1);
}

void DifferencePass::resizeSources(int width, int height) {
    if (sources_[0] && width_ == width && height_ == height) return;
    for (std::size_t k = 0; k < 2; ++k) {
        sources_[k] = makeImageTexture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
        sourceFbos_[k] = makeFramebuffer(sources_[k].get(), 0, "layout diff");
    }
    width_ = width;
    height_ = height;
}

// Both source panes out of the target into the copies, bound to texture units 0 and 1 (GL's rows run
// bottom-up: y flips). A blit, not glCopyTexSubImage2D: it also reads a multisampled target (MSAA),
// resolving the panes.
void DifferencePass::copySources(const Pane& a, const Pane& b, const RenderTarget& target) {
    const Pane* sources[2] = {&a, &b};
    GLuint from = target.framebuffer;
#if SHADELAB_GLES
    if (isMultisampled(target.framebuffer)) {
        if (!resolved_ || resolvedWidth_ != target.width || resolvedHeight_ != target.height) {
            resolved_ = makeImageTexture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, target.width, target.height);
            resolvedFbo_ = makeFramebuffer(resolved_.get(), 0, "layout diff (MSAA resolve)");
            resolvedWidth_ = target.width;
            resolvedHeight_ = target.height;
        }
        blitColor(target.framebuffer, 0, 0, resolvedFbo_.get(), 0, 0, target.width, target.height);
        from = resolvedFbo_.get();
    }
#endif
    for (std::size_t k = 0; k < 2; ++k) {
        blitColor(from, sources[k]->x, target.height - sources[k]->y - sources[k]->height, sourceFbos_[k].get(), 0, 0,
                  width_, height_);
        glActiveTexture(GLenum(GL_TEXTURE0 + k));
        glBindTexture(GL_TEXTURE_2D, sources_[k].get());
    }
}

}  // namespace shadelab
