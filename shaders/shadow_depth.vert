// Shadow-map depth pass: positions only, into one layer of a light's depth texture array. The view
// (a cube face, an orthographic or an area-sample perspective view, see render/cpu/shadow_projection.hpp)
// and the object transform come premultiplied. A glTF cut-out (SL_ALPHA_MODE SL_ALPHA_MASK) also
// passes what its alpha is made of, so that it casts a cut-out shadow (shadow_depth.frag).
#include "shared_defs.glsl"

layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;

uniform mat4 u_shadowClipFromObject;

#if defined(SL_ALPHA_MODE) && SL_ALPHA_MODE == SL_ALPHA_MASK
layout(location = SL_ATTRIB_TEXCOORD) in vec2 a_texcoord;
layout(location = SL_ATTRIB_COLOR) in vec4 a_color;
out vec2 v_texcoord;
out float v_vertexAlpha;
#endif

void main() {
#if defined(SL_ALPHA_MODE) && SL_ALPHA_MODE == SL_ALPHA_MASK
    v_texcoord = a_texcoord;
    v_vertexAlpha = a_color.a;
#endif
    gl_Position = u_shadowClipFromObject * vec4(a_posObject, 1.0);
}
