#include "render/progressive_pass.hpp"

#include "render/program.hpp"
#include "render/program_cache.hpp"

#include <glm/common.hpp>

#include <algorithm>

namespace shadelab {
namespace {

// The ordered-dither rank of (x, y) in a 2^bits square: bit-reversed interleaving of y and x ^ y.
unsigned bayerRank(unsigned x, unsigned y, int bits) {
    unsigned rank = 0;
    for (int b = 0; b < bits; ++b) {
        rank = (rank << 2) | (((x ^ y) >> b & 1u) << 1) | (y >> b & 1u);
    }
    return rank;
}

// The most samples any area light of `scene` has along each axis (1 without area lights).
glm::ivec2 largestAreaSamples(const Scene& scene) {
    glm::ivec2 largest(1);
    for (const Light& l : scene.lights)
        if (l.type == LightType::Area) largest = glm::max(largest, l.samples);
    return largest;
}

}  // namespace

std::vector<glm::ivec2> progressivePassOrder(const glm::ivec2& stride) {
    std::vector<glm::ivec2> order;
    for (int y = 0; y < stride.y; ++y)
        for (int x = 0; x < stride.x; ++x) order.emplace_back(x, y);
    int bits = 0;
    while ((1 << bits) < std::max(stride.x, stride.y)) ++bits;
    std::stable_sort(order.begin(), order.end(), [bits](const glm::ivec2& a, const glm::ivec2& b) {
        return bayerRank(unsigned(a.x), unsigned(a.y), bits) < bayerRank(unsigned(b.x), unsigned(b.y), bits);
    });
    return order;
}

void ProgressivePass::prepare(const Scene& scene, int width, int height, int stride, bool restart) {
    // Along each axis no stride beyond the largest sample count: such passes would have no samples.
    const glm::ivec2 s = glm::clamp(glm::ivec2(stride), glm::ivec2(1), largestAreaSamples(scene));
    if (width_ != width || height_ != height) {
        sumColor_ = makeImageTexture(GL_RGBA32F, GL_RGBA, GL_FLOAT, width, height);
        depth_ = makeImageTexture(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, width, height);
        sumFbo_ = makeFramebuffer(sumColor_.get(), depth_.get(), "progressive sampling (float sum)");
        width_ = width;
        height_ = height;
        restart = true;
    }
    if (restart || s != stride_) {
        stride_ = s;
        order_ = progressivePassOrder(s);
        done_ = 0;
    }
}

std::optional<AreaSamplePass> ProgressivePass::nextPass() const {
    if (done_ >= int(order_.size())) return std::nullopt;
    return AreaSamplePass{order_[std::size_t(done_)], stride_};
}

void ProgressivePass::resolveInto(const Scene& scene, const RenderTarget& target, const ShaderLibrary& shaders) {
    const GLuint program = resolveProgram(scene.outputEncoding, shaders);
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    glViewport(0, 0, target.width, target.height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, sumColor_.get());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, depth_.get());
    glActiveTexture(GL_TEXTURE0);
    glUseProgram(program);
    glUniform3f(glGetUniformLocation(program, "u_background"), scene.background.r, scene.background.g,
                scene.background.b);
    fullscreen_.draw(program);
    glDepthFunc(GL_LESS);
}

GLuint ProgressivePass::resolveProgram(OutputEncoding encoding, const ShaderLibrary& shaders) {
    gl::Program& resolve = resolve_[encoding == OutputEncoding::Srgb ? 1 : 0];
    if (!resolve) {
        resolve = buildProgram("resolve", shaders, {encodingDefine(encoding)}, kFullscreenVertex);
        glUseProgram(resolve.get());
        glUniform1i(glGetUniformLocation(resolve.get(), "u_sum"), 0);
        glUniform1i(glGetUniformLocation(resolve.get(), "u_depth"), 1);
    }
    return resolve.get();
}

}  // namespace shadelab
