#pragma once
// What the renderer's image passes share (the difference pane, progressive sampling's resolve, the
// readback): textures read texel for texel, framebuffers drawing into them, and one triangle over the
// viewport.
#include "render/gl_handles.hpp"

namespace shadelab {

// A width x height texture read with texelFetch (nearest, one level).
gl::Texture makeImageTexture(GLint internalFormat, GLenum format, GLenum type, int width, int height);
// A framebuffer drawing into `color` and, unless it is 0, `depth`. Throws std::runtime_error, naming
// `what`, when this GL cannot draw into them.
gl::Framebuffer makeFramebuffer(GLuint color, GLuint depth, const char* what);

// One triangle over the viewport, drawn with a program whose vertex stage is shaders/fullscreen.vert
// (kFullscreenVertex): it makes its corners from gl_VertexID, so the vertex array it binds is an empty
// one (a core profile draws only with one bound). Face culling is off for the draw and on after it.
class FullscreenTriangle {
public:
    void draw(GLuint program);

private:
    gl::VertexArray emptyVao_;  // made on the first draw
};

}  // namespace shadelab
