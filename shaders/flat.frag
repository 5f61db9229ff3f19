// Flat shading's fragments: each takes its triangle's colour from flat.vert as it is (`flat`).
#define SL_ONE_PER_TRIANGLE 1
#include "vertex_shading.glsl"

out vec4 o_color;

void main() {
    if (cutOut()) discard;                           // glTF's alpha MASK: not there
    vec3 L = shadedColor();                          // the triangle's L (times the texel where C varies)
    o_color = vec4(encodeOutput(L), outputAlpha());  // L is clamped already: encoded
}
