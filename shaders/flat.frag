#include "object_color.glsl"

#if SL_TEXTURED
flat in vec3 v_termsOfC;
flat in vec3 v_specular;
#else
flat in vec3 v_color;
#endif
out vec4 o_color;

void main() {
    if (cutOut()) discard;
#if SL_TEXTURED
    vec3 color = combineTerms(v_termsOfC, v_specular);
#else
    vec3 color = v_color;
#endif
    o_color = vec4(encodeOutput(color), outputAlpha());
}
