#pragma once
// The pixel probe: which surface point a pixel of the output image sees, and every term of the
// lecture's formula there, evaluated the way that pixel's shading mode evaluates it on the GPU:
//   phong    once, at the point, with the interpolated vertex normal renormalised (phong.frag);
//   gouraud  at the triangle's three corners with their vertex normals (gouraud.vert), the three
//            clamped colours then weighted by the point's perspective-correct barycentrics;
//   flat     once, at the triangle's centroid with its face normal (flat.vert, FlatMesh).
// With anisotropy each evaluation has its tangent frame likewise: the tangents interpolated (phong), the
// corner's (gouraud), the corners' averaged (flat: faceTangent); each made orthogonal to that N.
// On the back of a double-sided part every normal is flipped, as the shaders do (SL_DOUBLE_SIDED).
// The numbers are the CPU reference's (core/shading/lighting.hpp, shadeTerms), so the probe's total is the
// rendered pixel (tests/gl/probe_test.cpp checks that). With shadows on, the occlusion term v(p, I)
// is a ray cast on the CPU toward each light sample, the lecture's own definition; the renderer uses
// shadow maps, which agree with it except within a few shadow-map texels of a shadow's edge.
#include "core/geometry/camera.hpp"
#include "core/geometry/mesh.hpp"
#include "core/geometry/ray_cast.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/scene/scene.hpp"
#include "core/shading/environment.hpp"
#include "core/shading/lighting.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

// One light at one evaluation: the lecture's vectors and dot products, and the light's share.
struct ProbeLight {
    glm::vec3 towardLight{0.0f};  // I, unit (an area light: toward its centre; its shares sum its samples)
    float nDotI = 0.0f;
    glm::vec3 reflected{0.0f};  // R(I) = 2 (N.I) N - I
    float rDotV = 0.0f;
    glm::vec3 halfway{0.0f};  // H = normalize(I + V)
    float hDotN = 0.0f;
    // The lobe's exponent: k_e, or with anisotropy Ashikhmin and Shirley's at H (anisotropicExponent).
    float exponent = 0.0f;
    glm::vec3 diffuse{0.0f};   // L_l k_d C max(0, N.I), occlusion included (ShadingTerms::lights)
    glm::vec3 specular{0.0f};  // L_l k_s S spec_l (with the scene's normalisation and Fresnel)
    // Shadows on: light samples that reached the occlusion test (in front of the surface and of an area
    // light) and how many of them the light reaches. visibility = visible / tested (1 if none tested).
    int samplesTested = 0;
    int samplesVisible = 0;
    float visibility = 1.0f;
};

// One evaluation of the formula: where, with which normal, and every term.
struct ProbeEvaluation {
    enum class Site { Point, Centroid, Vertex };
    Site site = Site::Point;
    std::uint32_t vertex = 0;  // Site::Vertex: index into the mesh's vertices
    glm::vec3 posWorld{0.0f};
    glm::vec3 nrmWorld{0.0f};   // N, unit
    glm::vec3 viewWorld{0.0f};  // V, unit, toward the eye
    // Anisotropic reflection: the tangent frame there (T, B), as the mode's shader builds it from the
    // mesh's tangents (Mesh::tangents): interpolated (phong), the corner's (gouraud), the face's (flat).
    bool anisotropic = false;
    TangentFrame frame;
    ShadingTerms terms;  // ambient, diffuse, specular, shown (before clamping), total (clamped)
    // Mirror and glass (a material with k_r or k_t in a scene with an environment): R, T, the angles,
    // the indices, F and the two terms (core/shading/environment.hpp).
    bool mirrorGlass = false;
    EnvironmentTerm environment;
    std::vector<ProbeLight> lights;  // in the order of Scene::lights
};

// A shading mode's answer for the pixel.
struct ModeProbe {
    ShadingMode mode = ShadingMode::Phong;
    std::vector<ProbeEvaluation> evaluations;  // phong, flat: one; gouraud: the corners a, b, c
    glm::vec3 color{0.0f};   // linear, clamped: what the fragment shader encodes (gouraud: interpolated)
    glm::vec3 output{0.0f};  // after the scene's output encoding (sRGB or as is), in [0, 1]
    glm::ivec3 output8{0};   // the 8-bit value in the image: round(output * 255)
};

// A probed surface point, kept while the camera moves: the viewer re-evaluates it every frame.
struct ProbeAnchor {
    int x = 0, y = 0;  // the pixel it was set at
    int pane = 0;      // index into layoutPanes(): the mode evaluated is that pane's
    std::size_t object = 0, triangle = 0;
    glm::vec3 barycentric{1.0f / 3.0f};  // weights of the triangle's corners a, b, c
};

struct ProbeResult {
    int x = 0, y = 0;  // the pixel (top-left origin)
    int pane = -1;     // index into layoutPanes(); -1 in the diff layout's spare columns
    Pane paneRect;
    bool miss = true;           // nothing drawn there: the pixel is the background
    ProbeAnchor anchor;         // the surface point (when not a miss)
    glm::vec3 posWorld{0.0f};   // the point the pixel's centre sees
    Material material;          // as drawn: a glTF part's own base colour replaces `color` unless the scene set one;
                                // where C varies, `color` is the sampled C (base colour x texel)
    bool textured = false;      // C varies over the surface (a glTF texture or vertex colours, drawn)
    glm::vec2 texcoord{0.0f};   // textured: the texture coordinates at the point
    glm::vec3 texel{1.0f};      // textured: texture(texcoord) x COLOR_0 there, linear
    glm::vec3 baseColor{1.0f};  // textured: the part's base colour factor (C = baseColor x texel)
    // A glTF part's coverage (MeshPart): its mode and the alpha at the point (factor x texel x COLOR_0).
    // The probe reports the surface it hits; it does not composite a blended one over what is behind.
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alpha = 1.0f, alphaCutoff = 0.5f;
    bool doubleSided = false;  // the point's part is double-sided (a glTF material's doubleSided)
    bool backFace = false;     // and the eye sees its back: every mode evaluates with N flipped (glTF's rule)
    // One mode; the diff layout's difference pane: its two modes (diff.a, diff.b).
    std::vector<ModeProbe> modes;
    glm::ivec3 output8{0};  // the pixel: the mode's value, the difference pane's |a - b| * factor, or the background
};

// Throws InputError "FLAG: pixel X,Y is outside the WxH image" unless 0 <= x < width, 0 <= y < height.
void checkProbePixel(const Scene& scene, int x, int y, const std::string& flag);

// Probes pixel (x, y) of the scene's image (scene.width x scene.height, its layout's panes). `caster`
// must have been built from this scene and geometry; it finds the surface and, with shadows on,
// tests occlusion. Throws InputError when the pixel is outside the image.
ProbeResult probePixel(const Scene& scene, const SceneGeometry& geometry, const SceneRayCaster& caster, int x, int y);

// Evaluates an anchored surface point in the scene as it is now (camera, lights, material, layout).
// The anchor must name a triangle of `geometry` (validAnchor); its pane is clamped to the layout's.
ProbeResult probeAnchor(const Scene& scene, const SceneGeometry& geometry, const SceneRayCaster& caster,
                        const ProbeAnchor& anchor);
bool validAnchor(const Scene& scene, const SceneGeometry& geometry, const ProbeAnchor& anchor);

// The formula's terms at the probed pixel as its mode computes them (the formula overlay's values):
// phong's and flat's one evaluation; gouraud's three corners weighted by the point's barycentrics, as
// the colours are interpolated. `total` is the pixel's colour (linear, clamped). The first mode's, in
// the diff layout's difference pane; nullopt for a miss.
std::optional<ShadingTerms> probedTerms(const ProbeResult& result);
// "at pixel 1050,330 (Phong)": the pixel and the mode whose terms probedTerms gives.
std::string probedPlace(const ProbeResult& result);

// The result as JSON text (README, "Pixel probe", lists the fields).
std::string probeToJson(const Scene& scene, const ProbeResult& result);

}  // namespace shadelab
