// phong.frag with the formula's values read from phong_interpolated.vert's outputs instead of the
// uniform blocks (that file says why); the same main as phong.frag.
#include "lighting.glsl"

#define SL_INPUT_LIGHTS (SL_LIGHT_COUNT > 0 ? SL_LIGHT_COUNT : 1)
in vec3 v_posWorld;
in vec3 v_nrmWorld;
in vec3 v_toEyeWorld;
in vec3 v_toLightWorld[SL_INPUT_LIGHTS];
flat in vec3 v_C, v_S, v_A;
flat in vec4 v_k;
flat in vec3 v_lightColor[SL_INPUT_LIGHTS];

Material objectMaterial(vec3 texel) { return Material(v_C * texel, v_S, v_k.x, v_k.y, v_k.z, v_k.w); }
vec3 ambientLight() { return v_A; }
vec3 lightColor(int l) { return v_lightColor[l]; }
vec3 toEye(vec3 P) { return v_toEyeWorld; }
vec3 toLight(int l, vec3 P) { return v_toLightWorld[l]; }

#include "object_color.glsl"

out vec4 o_color;

void main() {
    if (cutOut()) discard;
    vec3 N = facingNormal(normalize(v_nrmWorld));
    vec3 L = shade(v_posWorld, N, objectTexel());
    o_color = fragmentColor(L);
}
