// Where the lecture's values come from: the uniform blocks (shaders/uniforms.glsl), which
// app/render/renderer.cpp fills from the scene. Every shading program reads them here, except Phong's
// speed variant, shaders/phong_interpolated.frag, which gets them from its vertex stage.
#include "lecture.glsl"
#include "uniforms.glsl"

// k_a, k_d, k_s, k_e, C and S. `texel`: where C varies over the surface (a glTF texture and vertex
// colours, shaders/object_color.glsl), C is the material's times it; 1 elsewhere.
Material objectMaterial(vec3 texel) {
    vec4 k = u_coefficients;
    return Material(u_color.rgb * texel, u_specularColor.rgb, k.x, k.y, k.z, k.w);
}
vec3 ambientLight() { return u_ambient.rgb; }                // A
vec3 lightColor(int l) { return u_lights[l].radiance.rgb; }  // L_l
vec3 toEye(vec3 P) { return u_eyeWorld.xyz - P; }
vec3 toLight(int l, vec3 P) {  // the light's position minus P; for a directional light, against its travel
    vec3 p = u_lights[l].positionOrDirection.xyz;
    return c_lightKind[l] == SL_LIGHT_DIRECTIONAL ? -p : p - P;
}
