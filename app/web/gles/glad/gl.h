#pragma once
// The web build's stand-in for glad's <glad/gl.h> (third_party/CMakeLists.txt puts this folder on the
// include path of the web build only). WebGL2 is OpenGL ES 3.0: emscripten links its functions
// directly, so there is nothing to load. The renderer is written against OpenGL 3.3 core; the few
// desktop calls it makes have an ES 3.0 equivalent, named here, or mean what ES does anyway:
//   glClearDepth(d)            glClearDepthf(d)
//   glDrawBuffer(b)            glDrawBuffers(1, &b)
//   glPolygonMode(f, GL_FILL)  nothing: ES fills polygons (the renderer asks for nothing else; its
//                              wireframe is lines, render/overlay_renderer.cpp)
//   glProvokingVertex(GL_LAST_VERTEX_CONVENTION)  nothing: ES's provoking vertex is always the last
// What has no equivalent is not called in the web build (SHADELAB_GLES): the shadow maps' border
// colour (render/shadow_maps.cpp) and the geometry shader that widens overlay lines
// (render/overlay_renderer.cpp); docs/web.md says what that changes.
#include <GLES3/gl3.h>

#define GL_FILL 0x1B02
#define GL_LAST_VERTEX_CONVENTION 0x8E4E
#define GL_GEOMETRY_SHADER 0x8DD9  // named so that shared code compiles; never created in the web build

typedef void (*GLADapiproc)(void);
typedef GLADapiproc (*GLADloadfunc)(const char* name);

inline void glClearDepth(double depth) { glClearDepthf(static_cast<GLfloat>(depth)); }
inline void glDrawBuffer(GLenum buffer) { glDrawBuffers(1, &buffer); }
inline void glPolygonMode(GLenum, GLenum) {}
inline void glProvokingVertex(GLenum) {}
