#pragma once
// The scene model: the one description of what is drawn. The JSON scene file (scene_json.hpp), the
// command line and the viewer's panel all edit this plain struct; the renderer only reads it.
// Defaults here are the documented defaults of the scene-file format (README, "Scene file").
#include "core/image/environment_image.hpp"
#include "core/scene/scene_limits.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

enum class ShadingMode { Flat, Gouraud, Phong };
enum class Layout { Single, Compare, Diff };
enum class ReflectionModel { Phong, BlinnPhong };
enum class OutputEncoding { Linear, Srgb };
enum class LightType { Point, Directional, Area, Spot };
enum class Attenuation { None, InverseSquare };
// Beyond the heuristic model (lighting.hpp has the exact formulas):
enum class SpecularNormalization { None, Energy };  // "energy": lobes normalised to constant reflected energy
enum class FresnelMode { None, Schlick, Exact };    // specular weighted by the Fresnel reflectance at V.H
// What mirrors and glass reflect and transmit, drawn as the background: none, two procedural ones
// (core/shading/environment.hpp), or an equirectangular image.
enum class EnvironmentKind { None, Room, Sky, Image };
// Term isolation: which addend(s) of the formula are drawn ("show"); Emissive: a glTF material's E.
enum class ShowTerm { All, Ambient, Diffuse, Specular, Light, Unlit, Emissive };

// Limits shared by the parser, the CLI, the sweep, the panel and the renderer: core/scene/scene_limits.hpp.

struct Material {
    glm::vec3 color{0.85f, 0.32f, 0.2f};  // C, the diffuse/ambient colour (linear RGB, 0..1)
    glm::vec3 specularColor{1.0f};        // S, the colour of the highlight
    float ka = 0.1f;                      // ambient weight
    float kd = 0.7f;                      // diffuse weight
    float ks = 0.5f;                      // specular weight
    float ke = 32.0f;                     // specular exponent ("size of the highlight")
    // True when the scene (or the viewer's panel) set `color`: it then also overrides a glTF model's
    // own base colours. A model given without a colour keeps the colours its file gives.
    bool colorSet = false;
    // E, the light the surface gives off, added to the sum: L = E + k_a A C + ... . Not part of the
    // scene format: a glTF material's emission (MeshPart::emissive), set where a part is shaded.
    glm::vec3 emissive{0.0f};
    // Anisotropic reflection ("anisotropy": [k_t, k_b]): Ashikhmin and Shirley's exponent replaces k_e,
    // k_t along the surface's tangent T and k_b along its bitangent B (core/shading/lighting.hpp,
    // anisotropicExponent). Off unless the scene or --anisotropy gives it; Blinn-Phong's lobe only.
    bool anisotropic = false;
    glm::vec2 anisotropy{32.0f};  // k_t, k_b (each in kExponentRange)
    // Mirror and glass ("mirror", "transmission"): added after the lecture's sum,
    //   k_r F env(R) + k_t (1 - F) env(T)     (core/shading/environment.hpp, environmentTerm)
    // with F the Fresnel reflectance of the scene's "fresnel" mode (1 for both weights under "none").
    float mirror = 0.0f;        // k_r (kUnitRange)
    float transmission = 0.0f;  // k_t (kUnitRange)
};

struct MeshSpec {
    enum class Type { UvSphere, IcoSphere, Torus, Cube, Plane, Gltf };
    Type type = Type::UvSphere;
    // uvsphere: `slices` around the y axis, `stacks` from pole to pole; 2*slices*(stacks-1) triangles
    int slices = 64;
    int stacks = 32;
    float radius = 1.0f;        // uvsphere, icosphere
    int subdivisions = 3;       // icosphere: 20*4^n triangles
    float majorRadius = 1.0f;   // torus: centre of the tube, around the y axis
    float minorRadius = 0.35f;  // torus: tube radius
    int majorSegments = 48;     // torus: segments around y
    int minorSegments = 24;     // torus: segments around the tube
    float size = 2.0f;          // cube: edge length; plane: edge length (square in x-z, facing +y)
    int planeSubdivisions = 1;  // plane: quads per edge
    std::string path;           // gltf: as written in the scene (relative to the scene file)
    std::string resolvedPath;   // gltf: the path that is read (filled in by the parser)

    bool operator==(const MeshSpec& o) const;
    bool operator!=(const MeshSpec& o) const { return !(*this == o); }
};

struct Transform {
    glm::vec3 translation{0.0f};
    glm::vec3 rotationDeg{0.0f};  // applied about x, then y, then z (R = Rz * Ry * Rx)
    glm::vec3 scale{1.0f};
};

struct SceneObject {
    MeshSpec mesh;
    Material material;
    Transform transform;
};

struct Light {
    LightType type = LightType::Point;
    glm::vec3 position{3.0f, 4.0f, 5.0f};      // point and spot lights: world space; area lights: the centre
    glm::vec3 direction{-1.0f, -1.0f, -1.0f};  // directional lights: the direction the light travels; spot: its axis
    glm::vec3 color{1.0f};
    float intensity = 1.0f;                       // area lights: of the whole rectangle (see lighting.hpp)
    Attenuation attenuation = Attenuation::None;  // point, spot and area lights
    // Inverse-square only: > 0 multiplies 1/r^2 by the window clamp(1 - (r/range)^4, 0, 1)^2 so the
    // light reaches exactly zero at `range` (glTF KHR_lights_punctual's recommendation); 0: no window.
    float range = 0.0f;
    // Area lights: a w x h rectangle centred at `position`, emitting on the side `normal` points to
    // (both sides when twoSided), evaluated as samples.x * samples.y point lights (lighting.hpp).
    glm::vec3 normal{0.0f, -1.0f, 0.0f};
    glm::vec2 size{1.0f, 1.0f};
    glm::ivec2 samples{4, 4};
    bool twoSided = false;
    // Spot lights: a point light whose light is confined to a cone around `direction`: full inside the
    // inner half-angle, none outside the outer one, glTF's smooth falloff between (lighting.hpp).
    float innerConeDeg = 15.0f;  // when not given: half the outer half-angle
    float outerConeDeg = 30.0f;
};

// Shadows (occlusion toward each light) and how the shadow maps are made. Biases are what keep a lit
// surface from shadowing itself ("acne") without lifting shadows off their casters ("peter-panning").
struct ShadowSettings {
    bool enabled = false;
    float normalBias = 1.5f;  // the looked-up point moves along its normal by this many shadow-map texels
    float depthBias = 1.5f;   // slope-scaled depth offset of the shadow pass (glPolygonOffset factor and units)
    int pcf = 1;              // percentage-closer filtering radius: (2*pcf+1)^2 lookups (point, directional)
    int mapSize = 1024;       // side of each shadow map (a point light has six), pixels
    int areaMapSize = 256;    // side of the map of each area-light sample (soft shadows average them)

    bool operator==(const ShadowSettings& o) const;
    bool operator!=(const ShadowSettings& o) const { return !(*this == o); }
};

// "environment": "room" | "sky" | a .png or .hdr file (relative to the scene file).
struct EnvironmentSpec {
    EnvironmentKind kind = EnvironmentKind::None;
    std::string path;                               // Image: as written in the scene or on the command line
    std::string resolvedPath;                       // Image: the path that was read
    std::shared_ptr<const EnvironmentImage> image;  // Image: its texels (read when the scene is read)

    bool operator==(const EnvironmentSpec& o) const { return kind == o.kind && resolvedPath == o.resolvedPath; }
    bool operator!=(const EnvironmentSpec& o) const { return !(*this == o); }
};

struct Camera {
    glm::vec3 eye{0.0f, 1.5f, 4.8f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDeg = 45.0f;  // vertical field of view of each pane
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
};

// Where the viewer draws and drags a light (the overlay's cross, the panel's label and arrow): its
// position, or for a directional light, which has none, a point against its direction from the
// camera's target, directionalHandleDistance away: 0.6 of the eye's distance, so the handle stays in
// front of the eye however the camera moves.
float directionalHandleDistance(const Camera& camera);
glm::vec3 lightHandle(const Light& light, const Camera& camera);

// What the formula draws: every term, one of them, one light's share, or the unlit colour C.
struct TermView {
    ShowTerm term = ShowTerm::All;
    int light = 0;  // ShowTerm::Light: index into Scene::lights (diffuse + specular of that light alone)

    bool operator==(const TermView& o) const { return term == o.term && (term != ShowTerm::Light || light == o.light); }
    bool operator!=(const TermView& o) const { return !(*this == o); }
};

// Layout "diff": panes a | b | |a - b| * factor, all of the same size, one camera. The difference is
// taken of the displayed 8-bit values (after clamping and output encoding).
struct DiffSettings {
    ShadingMode a = ShadingMode::Gouraud;
    ShadingMode b = ShadingMode::Phong;
    float factor = 4.0f;  // 1..kDiffFactorRange.hi
};

// "test": the scene's own settings as a screenshot test (`shadelab --test`, run/test_suite.hpp), over the
// command line's --max-diff, --mean-diff and --max-diff-pixels (the folder's defaults). Nothing here
// changes the picture.
struct TestSettings {
    std::optional<int> maxDiff;                  // "max_diff": the largest channel difference allowed, /255
    std::optional<float> meanDiff;               // "mean_diff": the largest mean difference allowed, /255
    std::optional<std::uint64_t> maxDiffPixels;  // "max_diff_pixels": at most this many pixels may differ
    // "masks": [x, y, w, h] rectangles in pixels (top-left origin) left out of the comparison (a clock, a
    // noisy corner), shown hatched in the report; parts outside the image are ignored.
    std::vector<glm::ivec4> masks;
    bool empty() const { return !maxDiff && !meanDiff && !maxDiffPixels && masks.empty(); }
};

// "viewer": how the viewer opens the scene as a lecture preset's slide, so a slide can show the lecture's
// figure by itself: a probed point, the intersection diagram at it, the panel's sections. Headless runs
// draw nothing of it (--probe and --intersection say there what to draw).
struct ViewerStart {
    // "probe": [x, y], a pixel of the scene's "size" (top-left origin); the viewer probes the same point
    // of its view (scaled by the view's height about its centre, as the camera's vertical field of view is).
    std::optional<glm::ivec2> probe;
    glm::ivec2 probeOf{0, 0};   // the scene's size the probe was given in
    bool intersection = false;  // "intersection": the diagram at the probe (the viewer's key I)
    std::optional<std::vector<std::string>> panelSections;  // "panel_sections": exactly these open
    std::string plot;  // "plot": the panel's Plots section open, scrolled to this plot
    bool empty() const { return !probe && !intersection && !panelSections && plot.empty(); }
    // The pixel of a width x height view that shows what `probe` shows at `probeOf` (clamped into it).
    glm::ivec2 probeIn(int width, int height) const;
};

struct Scene {
    std::vector<SceneObject> objects{SceneObject{}};
    ShadingMode shading = ShadingMode::Phong;
    Layout layout = Layout::Single;
    ReflectionModel reflection = ReflectionModel::BlinnPhong;
    glm::vec3 ambient{1.0f};
    std::vector<Light> lights{Light{}};
    ShadowSettings shadows;
    Camera camera;
    glm::vec3 background{0.08f, 0.08f, 0.1f};
    int width = 1280;
    int height = 720;
    OutputEncoding outputEncoding = OutputEncoding::Linear;
    SpecularNormalization specularNormalization = SpecularNormalization::None;
    FresnelMode fresnel = FresnelMode::None;
    float ior = 1.5f;             // eta2 / eta1 at every surface (eta1 = 1: air); used when fresnel != none
    EnvironmentSpec environment;  // "environment": what k_r and k_t see, and the background when set
    TermView show;                // "show": "all" | "ambient" | "diffuse" | "specular" | "light:N" | "unlit"
    DiffSettings diff;            // layout "diff"
    std::string title;            // lecture presets: shown by the viewer's playlist (and nothing else)
    std::string caption;          // one sentence under the title
    bool textures = true;         // "textures": glTF models' base colour textures and vertex colours (C varies)
    TestSettings test;            // "test": thresholds and masks for `shadelab --test`
    ViewerStart viewer;           // "viewer": the probe, diagram and panel sections a preset opens with

    // Bookkeeping, not part of the file format:
    bool cameraGiven = false;          // false: a glTF model may be auto-framed
    int modelCamera = -1;              // --camera N: the first glTF model's camera N replaces the scene's
    bool lightsGiven = false;          // false: auto-framing may move the default light with the camera
    bool outputEncodingGiven = false;  // false: a scene with a glTF model is written sRGB-encoded (frameIfNeeded)
    bool emissiveModel = false;   // a glTF model's material gives off light, E (frameIfNeeded; the formula shows E)
    bool usesObjectList = false;  // written back as "objects" rather than the one-object shorthand
    std::string sourcePath;       // the file it came from ("" for the built-in default)
};

// Names as they appear in scene files and on the command line.
const char* toString(ShadingMode m);
const char* toString(Layout l);
const char* toString(ReflectionModel r);
const char* toString(MeshSpec::Type t);
const char* toString(Attenuation a);
const char* toString(LightType t);
const char* toString(OutputEncoding e);
const char* toString(SpecularNormalization n);
const char* toString(FresnelMode f);
const char* toString(EnvironmentKind k);  // "none", "room", "sky", "image"
std::string toString(const TermView& t);  // "all", ..., "light:2"

}  // namespace shadelab
