// Depth only: the fixed-function depth (with the pass's slope-scaled offset) is all that is stored.
// A cut-out's fragments below the cutoff store nothing (the alpha of shaders/object_color.glsl).
#include "shared_defs.glsl"

#if defined(SL_ALPHA_MODE) && SL_ALPHA_MODE == SL_ALPHA_MASK
in vec2 v_texcoord;
in float v_vertexAlpha;
uniform sampler2D u_baseColorTexture;  // on unit SL_TEXTURE_BASE_COLOR
uniform float u_alpha;                 // the base colour factor's alpha
uniform float u_alphaCutoffValue;
#endif

void main() {
#if defined(SL_ALPHA_MODE) && SL_ALPHA_MODE == SL_ALPHA_MASK
    if (u_alpha * texture(u_baseColorTexture, v_texcoord).a * v_vertexAlpha < u_alphaCutoffValue) discard;
#endif
}
