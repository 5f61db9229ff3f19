// Phong shading: the lecture's formula (shaders/lecture.glsl) evaluated for every fragment, with the
// interpolated normal renormalised first.
#include "lighting.glsl"
#include "values_from_blocks.glsl"
#include "object_color.glsl"

in vec3 v_posWorld;
in vec3 v_nrmWorld;
out vec4 o_color;

void main() {
    if (cutOut()) discard;                            // glTF's alpha MASK: not there
    vec3 N = facingNormal(normalize(v_nrmWorld));     // flipped on the back of a double-sided surface
    vec3 L = shade(v_posWorld, N, objectTexel());     // the lecture's L and what this program adds
    o_color = fragmentColor(L);                       // clamped to [0, 1] and encoded
}
