// Shared by the GLSL programs and by C++ (app/render/gpu_blocks.hpp includes this file): attribute
// locations, uniform-block bindings and limits have one definition. Only #define lines belong here.
#ifndef SL_SHARED_DEFS_GLSL
#define SL_SHARED_DEFS_GLSL

#define SL_ATTRIB_POSITION 0       // a_posObject
#define SL_ATTRIB_NORMAL 1         // a_nrmObject (flat: a_faceNrmObject)
#define SL_ATTRIB_CENTROID 2       // flat only: a_centroidObject (flat_packed.vert: two vec4s in 0 and 2)
#define SL_ATTRIB_TEXCOORD 3       // a_texcoord (SL_TEXTURED: shaders/object_color.glsl)
#define SL_ATTRIB_COLOR 4          // a_color (SL_TEXTURED)
#define SL_ATTRIB_INSTANCE 5       // a_instanceFromPart, a mat4 in locations 5..8 (SL_INSTANCED: shaders/instancing.glsl)
#define SL_ATTRIB_EMISSIVE_TEXCOORD 9  // a_emissiveTexcoord (SL_TEXTURED with SL_EMISSIVE_TEXTURE)
#define SL_ATTRIB_TANGENT 10       // a_tanObject, xyz the tangent, w the handedness (SL_ANISOTROPY; flat: a_faceTanObject)
#define SL_FLAT_NORMAL_Z_NEGATIVE 3.0  // added to the face normal's y where its z is negative (flat_packed.vert)

#define SL_BINDING_FRAME 0         // FrameBlock: camera and lights, one per pane
#define SL_BINDING_OBJECT 1        // ObjectBlock: transform and material, one per object

#define SL_MAX_LIGHTS 16
#define SL_MAX_INTERPOLATED_LIGHTS 3  // Phong's interpolated inputs fit GL 3.3's 60 varying components (phong_interpolated.vert)
#define SL_TEXTURE_SHADOW_MAPS 0       // u_shadowMaps: point, spot and directional lights' layers (shaders/shadows.glsl)
#define SL_TEXTURE_AREA_SHADOW_MAPS 1  // u_areaShadowMaps: area lights' layers
#define SL_TEXTURE_BASE_COLOR 2        // u_baseColorTexture (shaders/object_color.glsl)
#define SL_TEXTURE_EMISSIVE 3          // u_emissiveTexture (shaders/object_color.glsl)
#define SL_TEXTURE_ENVIRONMENT 4       // u_environmentMap: an image environment (shaders/environment.glsl)

#define SL_LIGHT_POINT 0
#define SL_LIGHT_DIRECTIONAL 1
#define SL_LIGHT_AREA 2
#define SL_LIGHT_SPOT 3                        // a point light confined to a cone (lighting.glsl, spotFalloff)
#define SL_ATTENUATION_NONE 0
#define SL_ATTENUATION_INVERSE_SQUARE 1
#define SL_ATTENUATION_INVERSE_SQUARE_RANGE 2  // 1/r^2 * clamp(1 - (r/range)^4, 0, 1)^2
#define SL_AREA_JITTER_SEED 0x5ade1abU         // area-light sample jitter (core/shading/lighting.hpp, areaSampleOffset)
#define SL_REFLECTION_PHONG 0
#define SL_REFLECTION_BLINN_PHONG 1
#define SL_ENCODING_LINEAR 0
#define SL_ENCODING_SRGB 1
// Beyond the heuristic model (core/shading/lighting.hpp); only scenes that use them get these defines.
#define SL_NORMALIZATION_NONE 0
#define SL_NORMALIZATION_ENERGY 1              // lobe * n(k_e) / n(SL_ENERGY_REFERENCE_EXPONENT)
#define SL_ENERGY_REFERENCE_EXPONENT 32.0      // k_e at which "energy" looks like "none"
#define SL_FRESNEL_NONE 0
#define SL_FRESNEL_SCHLICK 1
#define SL_FRESNEL_EXACT 2
#define SL_SHOW_ALL 0                          // term isolation ("show")
#define SL_SHOW_AMBIENT 1
#define SL_SHOW_DIFFUSE 2
#define SL_SHOW_SPECULAR 3
#define SL_SHOW_LIGHT 4                        // one light's diffuse + specular: SL_SHOW_LIGHT_INDEX
#define SL_SHOW_UNLIT 5                        // the material colour C, no lighting
#define SL_SHOW_EMISSIVE 6                     // E, the light the surface gives off
// Mirror and glass (SL_ENVIRONMENT; core/shading/environment.hpp): what env(d) is, and the procedural
// environments' constants, read by shaders/environment.glsl and core/shading/environment.cpp alike.
#define SL_ENVIRONMENT_NONE 0
#define SL_ENVIRONMENT_ROOM 1
#define SL_ENVIRONMENT_SKY 2
#define SL_ENVIRONMENT_IMAGE 3
#define SL_ROOM_EDGE 0.01                      // walls, floor and ceiling meet over this much of |d|'s components
#define SL_ROOM_TILES 2.0                      // checker periods per room half-width (8 tiles across the floor)
#define SL_ROOM_TILE_EDGE 0.02                 // the tiles' edges, in periods
#define SL_ROOM_WALL_RIGHT 0.80, 0.16, 0.10    // +x: red
#define SL_ROOM_WALL_LEFT 0.12, 0.55, 0.18     // -x: green
#define SL_ROOM_WALL_BACK 0.15, 0.28, 0.80     // +z (behind the default camera): blue
#define SL_ROOM_WALL_FRONT 0.85, 0.78, 0.55    // -z (ahead): warm white
#define SL_ROOM_CEILING 0.95, 0.95, 0.92
#define SL_ROOM_TILE_LIGHT 0.90, 0.90, 0.88
#define SL_ROOM_TILE_DARK 0.06, 0.06, 0.07
#define SL_SKY_ZENITH 0.18, 0.36, 0.85
#define SL_SKY_HORIZON 0.78, 0.86, 0.95
#define SL_SKY_GROUND 0.24, 0.21, 0.18
#define SL_SKY_SUN_DIRECTION 0.45, 0.45, -0.77 // towards the sun (normalised where used): ahead, up and right
#define SL_SKY_SUN 8.0, 7.6, 6.8               // the sun's disc: brighter than 1, so a mirror shows it white
#define SL_SKY_SUN_INNER_COS 0.99966           // cos 1.5 degrees: full disc inside
#define SL_SKY_SUN_OUTER_COS 0.99756           // cos 4 degrees: none outside
#define SL_ALPHA_OPAQUE 0                      // glTF alphaMode (SL_ALPHA_MODE): alpha ignored
#define SL_ALPHA_MASK 1                        // fragments below the cutoff discarded (a cut-out)
#define SL_ALPHA_BLEND 2                       // the colour written with its alpha, blended over what is behind

#endif
