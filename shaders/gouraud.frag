#include "lighting.glsl"
#include "object_color.glsl"

#if SL_TEXTURED
in vec3 v_termsOfC;
in vec3 v_specular;
#else
in vec3 v_color;
#endif
out vec4 o_color;

void main() {
#if SL_TEXTURED
    vec3 color = clamp(objectTexel() * v_termsOfC + v_specular, 0.0, 1.0);
#else
    vec3 color = v_color;
#endif
    o_color = vec4(encodeOutput(color), 1.0);
}
