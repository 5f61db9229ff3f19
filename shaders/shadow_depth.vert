// Shadow-map depth pass: positions only, into one layer of a light's depth texture array. The view
// (a cube face, an orthographic or an area-sample perspective view, see render/cpu/shadow_projection.hpp)
// and the object transform come premultiplied.
#include "shared_defs.glsl"

layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;

uniform mat4 u_shadowClipFromObject;

void main() {
    gl_Position = u_shadowClipFromObject * vec4(a_posObject, 1.0);
}
