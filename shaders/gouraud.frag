// Gouraud shading's fragments: each takes the colour interpolated from gouraud.vert's vertices.
#include "vertex_shading.glsl"

out vec4 o_color;

void main() {
    if (cutOut()) discard;                           // glTF's alpha MASK: not there
    vec3 L = shadedColor();                          // the interpolated L (times the texel where C varies)
    o_color = vec4(encodeOutput(L), outputAlpha());  // L is clamped already: encoded
}
