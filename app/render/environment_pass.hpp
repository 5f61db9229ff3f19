#pragma once
// The scene's environment on the GL side (--environment; core/shading/environment.hpp): an image
// environment's texels as a float texture on unit SL_TEXTURE_ENVIRONMENT, which the mirror-and-glass
// programs and the background read with texelFetch, and the background itself (shaders/background.frag),
// env(d) along each pixel's viewing direction.
#include "core/geometry/camera.hpp"
#include "core/scene/scene.hpp"
#include "render/gl_handles.hpp"
#include "render/image_pass.hpp"
#include "render/render_target.hpp"
#include "render/shader_library.hpp"

#include <map>
#include <memory>

namespace shadelab {

// SL_ENVIRONMENT_* for an environment kind (SL_ENVIRONMENT_NONE for none).
int environmentDefine(EnvironmentKind kind);

class EnvironmentPass {
public:
    // An image environment's texture uploaded (once per image) and bound on SL_TEXTURE_ENVIRONMENT;
    // nothing for the procedural ones. InputError when the image is larger than this GL's textures.
    void bindTexture(const Scene& scene);
    // The background of `pane` (the viewport is set here). `uncoveredOnly`: only where the depth buffer holds the far
    // plane (after progressive sampling's resolve, which leaves the surfaces' depth); else over the whole pane, depth
    // untouched.
    void drawBackground(const Scene& scene, const Pane& pane, const RenderTarget& target, const ShaderLibrary& shaders,
                        bool uncoveredOnly);

private:
    gl::Texture texture_;
    std::shared_ptr<const EnvironmentImage> uploaded_;  // the image texture_ holds
    std::map<std::string, gl::Program> programs_;       // by environment kind and output encoding
    FullscreenTriangle fullscreen_;
};

}  // namespace shadelab
