#pragma once
// A frame's uniform blocks in one upload, for the scene's draws (Renderer) and the overlays
// (OverlayRenderer): a FrameBlock per pane, then the ObjectBlocks, each at an offset that
// glBindBufferRange accepts (GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT), bound to SL_BINDING_FRAME and
// SL_BINDING_OBJECT before a draw. One upload a frame, instead of one per draw: llvmpipe copies a
// buffer on every glBufferSubData while a draw may still read it.
#include "render/gl_handles.hpp"
#include "render/gpu_blocks.hpp"

#include <cstddef>
#include <vector>

namespace shadelab {

class UniformStager {
public:
    UniformStager();  // a GL context must be current

    // Starts a frame of `frames` FrameBlocks and `objects` ObjectBlocks (all zero until set).
    void begin(std::size_t frames, std::size_t objects);
    void setFrame(std::size_t index, const gpu::FrameBlock& block);
    void setObject(std::size_t index, const gpu::ObjectBlock& block);
    void upload();  // after the blocks are set, before the first bind
    void bindFrame(std::size_t index) const;
    void bindObject(std::size_t index) const;

private:
    gl::Buffer buffer_;
    std::size_t frameStride_ = 0, objectStride_ = 0, objectsOffset_ = 0;
    std::vector<unsigned char> staging_;
};

}  // namespace shadelab
