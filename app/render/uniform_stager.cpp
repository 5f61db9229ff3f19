#include "render/uniform_stager.hpp"

#include <cstring>

namespace shadelab {
namespace {

std::size_t alignUp(std::size_t n, std::size_t a) { return (n + a - 1) / a * a; }

}  // namespace

UniformStager::UniformStager() : buffer_(gl::makeBuffer()) {
    GLint alignment = 0;
    glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
    const std::size_t a = alignment > 0 ? std::size_t(alignment) : 256;
    frameStride_ = alignUp(sizeof(gpu::FrameBlock), a);
    objectStride_ = alignUp(sizeof(gpu::ObjectBlock), a);
}

void UniformStager::begin(std::size_t frames, std::size_t objects) {
    objectsOffset_ = frameStride_ * frames;
    staging_.assign(objectsOffset_ + objectStride_ * objects, 0);
}

void UniformStager::setFrame(std::size_t index, const gpu::FrameBlock& block) {
    std::memcpy(staging_.data() + index * frameStride_, &block, sizeof block);
}

void UniformStager::setObject(std::size_t index, const gpu::ObjectBlock& block) {
    std::memcpy(staging_.data() + objectsOffset_ + index * objectStride_, &block, sizeof block);
}

void UniformStager::upload() {
    glBindBuffer(GL_UNIFORM_BUFFER, buffer_.get());
    glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(staging_.size()), staging_.data(), GL_STREAM_DRAW);
}

void UniformStager::bindFrame(std::size_t index) const {
    glBindBufferRange(GL_UNIFORM_BUFFER, SL_BINDING_FRAME, buffer_.get(), GLintptr(index * frameStride_),
                      sizeof(gpu::FrameBlock));
}

void UniformStager::bindObject(std::size_t index) const {
    glBindBufferRange(GL_UNIFORM_BUFFER, SL_BINDING_OBJECT, buffer_.get(),
                      GLintptr(objectsOffset_ + index * objectStride_), sizeof(gpu::ObjectBlock));
}

}  // namespace shadelab
