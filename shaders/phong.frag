// The interpolated normal is renormalised here, per fragment, before the model is evaluated.
#include "lighting.glsl"

in vec3 v_posWorld;
in vec3 v_nrmWorld;
out vec4 o_color;

void main() {
    o_color = vec4(encodeOutput(shadeLecture(v_posWorld, normalize(v_nrmWorld))), 1.0);
}
