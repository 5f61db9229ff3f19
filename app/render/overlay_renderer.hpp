#pragma once
// Teaching overlays drawn on top of what Renderer drew: wireframe edges, vertex and face normals as
// short lines, and markers at the lights. Kept out of Renderer so the shading programs and their images
// (which the golden tests pin) are untouched; it draws with its own program (shaders/overlay.*) and its
// own uniform buffer, into the same target and pane layout, testing against the depth Renderer left.
#include "core/geometry/scene_geometry.hpp"
#include "core/scene/scene.hpp"
#include "core/ui/view_names.hpp"
#include "render/gl_handles.hpp"
#include "render/renderer.hpp"
#include "render/shader_library.hpp"
#include "render/uniform_stager.hpp"

#include <glm/vec4.hpp>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace shadelab {

// Which overlays to draw; all off draws nothing.
struct OverlayOptions {
    bool wireframe = false;
    bool vertexNormals = false;
    bool faceNormals = false;
    bool tangents = false;  // each vertex's tangent T (Mesh::tangents: anisotropic reflection's), as long as a normal
    bool lightMarkers = false;
    float normalScale = 0.12f;  // normal line length as a share of each object's bounding radius
    // Pixels wide: light markers, sample markers and arrows (the probe's N, I, V, R, H); normals get
    // three quarters and the wireframe half of it, at least 1. The viewer thickens them with the UI
    // scale; 1 draws plain one-pixel GL lines (headless frames, the golden images).
    // An area light (index into Scene::lights; -1: none) whose rectangle, stratification cells and
    // nx x ny sample positions are marked: the light selected in the viewer's panel.
    int sampleMarkersLight = -1;
    float lineWidth = 1.0f;
    bool any() const {
        return wireframe || vertexNormals || faceNormals || tangents || lightMarkers || sampleMarkersLight >= 0;
    }
    // The switch of an overlay the command line and the panel name (core/ui/view_names.hpp).
    bool& shown(Overlay overlay) {
        switch (overlay) {
        case Overlay::Wireframe: return wireframe;
        case Overlay::VertexNormals: return vertexNormals;
        case Overlay::FaceNormals: return faceNormals;
        case Overlay::Tangents: return tangents;
        case Overlay::LightMarkers: break;
        }
        return lightMarkers;
    }
};

// An arrow in world space (the pixel probe's N, I, V, R, H), drawn with a head at `toWorld`. A zero
// length arrow is drawn as a small cross: a marker at a point.
struct OverlayArrow {
    glm::vec3 fromWorld{0.0f};
    glm::vec3 toWorld{0.0f};
    glm::vec4 color{1.0f};  // linear RGB and alpha
    int pane = -1;          // index into the layout's panes: drawn only there; -1: in every pane
};

class OverlayRenderer {
public:
    // Needs a current GL 3.3 context whose entry points are loaded (construct it after a Renderer).
    // Throws ShaderError if the overlay program does not build.
    explicit OverlayRenderer(const ShaderLibrary& shaders);

    // Line buffers are built lazily, per object and kind, the first time an overlay needs them.
    void setGeometry(std::shared_ptr<const SceneGeometry> geometry);
    // Draws the enabled overlays and the arrows into every pane of the scene's layout. Call right
    // after Renderer::render() on the same target, before anything clears its depth buffer.
    void render(const Scene& scene, const RenderTarget& target, const OverlayOptions& options,
                const std::vector<OverlayArrow>& arrows = {});

private:
    enum LineKind { Edges, VertexNormals, FaceNormals, Tangents, kLineKinds };
    struct Lines {
        gl::VertexArray vao;
        gl::Buffer vertices;
        GLsizei vertexCount = 0;
    };
    const Lines& lines(std::size_t object, LineKind kind);
    // Lines given in world space (light markers, sample markers, arrows), one colour per run.
    void drawWorldLines(const std::vector<float>& data, const std::vector<std::pair<GLint, glm::vec4>>& runs,
                        std::size_t identityObject);
    // render()'s steps: the matrices of every pane and object, and one object's lines in the bound pane.
    void stageMatrices(const Scene& scene, const std::vector<Pane>& panes, std::size_t objects);
    void drawObjectLines(const Scene& scene, const OverlayOptions& options, std::size_t object);
    void drawLights(const Scene& scene, std::size_t identityObject);
    void drawAreaSamples(const Scene& scene, const Light& light, std::size_t identityObject);
    void drawArrows(const Scene& scene, const Pane& pane, int paneIndex, const std::vector<OverlayArrow>& arrows,
                    std::size_t identityObject);

    // One-pixel GL lines, and lines widened to quads by shaders/overlay_wide.geom.
    struct LineProgram {
        gl::Program program;
        GLint normalLength = -1, depthBias = -1, color = -1, viewportSize = -1, lineWidth = -1, tangentTips = -1;
    };
    static LineProgram lineProgram(gl::Program program);
    // Makes the program for lines `pixels` wide current (and sets its width and pane size).
    const LineProgram& useWidth(float pixels);
    LineProgram thin_, wide_;
    const LineProgram* current_ = nullptr;
    float paneWidth_ = 1.0f, paneHeight_ = 1.0f, lineWidth_ = 1.0f;
    std::shared_ptr<const SceneGeometry> geometry_;
    std::vector<std::array<Lines, kLineKinds>> lines_;  // per object
    std::vector<float> objectRadius_;                   // per object, object space
    Lines worldLines_;                                  // rebuilt every draw (a few hundred vertices at most)
    UniformStager uniforms_;  // a FrameBlock per pane; an ObjectBlock per object, then the identity
};

}  // namespace shadelab
