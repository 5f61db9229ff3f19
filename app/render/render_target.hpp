#pragma once
// Where the renderer and its passes draw: a framebuffer the front end made (or the context's own) and
// its size in pixels.
#include <glad/gl.h>

namespace shadelab {

struct RenderTarget {
    GLuint framebuffer = 0;  // 0: the context's default framebuffer
    int width = 0;
    int height = 0;
};

}  // namespace shadelab
