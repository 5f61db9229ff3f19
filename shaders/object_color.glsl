// The material colour C where it varies over the surface (SL_TEXTURED): a glTF model's base colour
// texture and its vertex colours (COLOR_0). The material's own C (the base colour factor) is in the
// ObjectBlock's products already (u_color, k_a A C, L_l k_d C); what varies is the factor
//
//     texel = texture(u_baseColorTexture, uv).rgb * COLOR_0,    C = u_color * texel,
//
// read per fragment in every shading mode: the vertex stage passes the texture coordinates and the
// vertex colour on (passObjectColor), the fragment stage samples (objectTexel). Without SL_TEXTURED
// the texel is 1 and the programs are the ones they always were.
#include "shared_defs.glsl"

#ifndef SL_TEXTURED
#define SL_TEXTURED 0
#endif

#if SL_TEXTURED && defined(SL_VERTEX_STAGE)
layout(location = SL_ATTRIB_TEXCOORD) in vec2 a_texcoord;  // the texture's TEXCOORD_n, transformed
layout(location = SL_ATTRIB_COLOR) in vec3 a_color;        // COLOR_0, linear (white where there is none)
out vec2 v_texcoord;
out vec3 v_vertexColor;
void passObjectColor() {
    v_texcoord = a_texcoord;
    v_vertexColor = a_color;
}
#elif SL_TEXTURED
in vec2 v_texcoord;
in vec3 v_vertexColor;
uniform sampler2D u_baseColorTexture;  // on unit SL_TEXTURE_BASE_COLOR; an sRGB texture: samples are linear
vec3 objectTexel() { return texture(u_baseColorTexture, v_texcoord).rgb * v_vertexColor; }
#else
void passObjectColor() {}
vec3 objectTexel() { return vec3(1.0); }
#endif
