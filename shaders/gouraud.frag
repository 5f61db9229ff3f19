#include "object_color.glsl"

#if SL_TEXTURED
in vec3 v_termsOfC;
in vec3 v_specular;
#else
in vec3 v_color;
#endif
#if SL_DOUBLE_SIDED && SL_TEXTURED
in vec3 v_termsOfCBack;  // gouraud.vert's values with -N, for the back of a double-sided surface
in vec3 v_specularBack;
#elif SL_DOUBLE_SIDED
in vec3 v_colorBack;
#endif
out vec4 o_color;

void main() {
    if (cutOut()) discard;
#if SL_TEXTURED
    vec3 termsOfC = v_termsOfC, specular = v_specular;
#if SL_DOUBLE_SIDED
    if (!gl_FrontFacing) {  // glTF's doubleSided: the back side, lit with -N
        termsOfC = v_termsOfCBack;
        specular = v_specularBack;
    }
#endif
    vec3 color = combineTerms(termsOfC, specular);
#else
    vec3 color = v_color;
#if SL_DOUBLE_SIDED
    if (!gl_FrontFacing) color = v_colorBack;  // glTF's doubleSided: the back side, lit with -N
#endif
#endif
    o_color = vec4(encodeOutput(color), outputAlpha());
}
