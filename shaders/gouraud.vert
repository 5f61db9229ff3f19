// Gouraud shading: the colour is evaluated at each vertex with its vertex normal; the rasterizer
// interpolates the colours (perspective-correct) across the triangle.
#include "lighting.glsl"
#include "values_from_blocks.glsl"
#include "object_color.glsl"
#include "instancing.glsl"

layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;
layout(location = SL_ATTRIB_NORMAL) in vec3 a_nrmObject;

#if SL_TEXTURED
// C varies across the triangle: the formula's two parts are interpolated and combined per fragment.
out vec3 v_termsOfC;  // k_a A C + sum v L_l k_d C (N.I), with the material's C
out vec3 v_specular;  // sum v L_l k_s S spec_l
#else
out vec3 v_color;
#endif
#if SL_DOUBLE_SIDED
// glTF's doubleSided: a vertex cannot know which side of its triangles the eye sees, so, as OpenGL's
// fixed-function two-sided lighting did (GL_LIGHT_MODEL_TWO_SIDE), the formula is evaluated for N
// and for -N, and gouraud.frag picks by gl_FrontFacing.
#if SL_TEXTURED
out vec3 v_termsOfCBack;  // the same with -N
out vec3 v_specularBack;
#else
out vec3 v_colorBack;
#endif
#endif

void main() {
    vec4 posWorld = worldFromObject() * vec4(a_posObject, 1.0);
    vec3 nrmWorld = normalize(normalToWorld(a_nrmObject));
#if SL_TEXTURED
    v_termsOfC = shadeLectureTermsOfC(posWorld.xyz, nrmWorld);
    v_specular = shadeLectureSpecular(posWorld.xyz, nrmWorld);
    passObjectColor();
#else
    v_color = shadeLecture(posWorld.xyz, nrmWorld);
#endif
#if SL_DOUBLE_SIDED && SL_TEXTURED
    v_termsOfCBack = shadeLectureTermsOfC(posWorld.xyz, -nrmWorld);
    v_specularBack = shadeLectureSpecular(posWorld.xyz, -nrmWorld);
#elif SL_DOUBLE_SIDED
    v_colorBack = shadeLecture(posWorld.xyz, -nrmWorld);
#endif
    gl_Position = u_clipFromWorld * posWorld;
}
