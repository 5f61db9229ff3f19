#include "render/overlay_renderer.hpp"

#include "core/geometry/camera.hpp"
#include "core/geometry/mesh.hpp"
#include "core/shading/lighting.hpp"
#include "render/gpu_blocks.hpp"
#include "render/program.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace shadelab {
namespace {

// Line vertices: object-space position, then the normal that marks a normal line's tip (zero elsewhere).
constexpr int kFloatsPerVertex = 6;

void pushVertex(std::vector<float>& out, const glm::vec3& pos, const glm::vec3& tipNormal = glm::vec3(0.0f)) {
    out.insert(out.end(), {pos.x, pos.y, pos.z, tipNormal.x, tipNormal.y, tipNormal.z});
}

std::vector<float> edgeLines(const Mesh& mesh) {
    // Each edge once, though two triangles share it: sort the (low, high) index pairs and drop repeats.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = mesh.indices[t + std::size_t(e)], b = mesh.indices[t + std::size_t((e + 1) % 3)];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::vector<float> out;
    out.reserve(edges.size() * 2 * kFloatsPerVertex);
    for (const auto& [a, b] : edges) {
        pushVertex(out, mesh.positions[a]);
        pushVertex(out, mesh.positions[b]);
    }
    return out;
}

std::vector<float> vertexNormalLines(const Mesh& mesh) {
    std::vector<float> out;
    out.reserve(mesh.positions.size() * 2 * kFloatsPerVertex);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        pushVertex(out, mesh.positions[i]);
        pushVertex(out, mesh.positions[i], mesh.normals[i]);
    }
    return out;
}

// From each vertex along its tangent T (Mesh::tangents), the direction k_t applies along.
std::vector<float> tangentLines(const Mesh& mesh) {
    std::vector<float> out;
    out.reserve(mesh.tangents.size() * 2 * kFloatsPerVertex);
    for (std::size_t i = 0; i < mesh.positions.size() && i < mesh.tangents.size(); ++i) {
        pushVertex(out, mesh.positions[i]);
        pushVertex(out, mesh.positions[i], glm::vec3(mesh.tangents[i]));
    }
    return out;
}

// From each triangle's centroid along the lecture's face normal (the one flat shading uses).
std::vector<float> faceNormalLines(const Mesh& mesh) {
    std::vector<float> out;
    out.reserve(mesh.indices.size() / 3 * 2 * kFloatsPerVertex);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3& a = mesh.positions[mesh.indices[t]];
        const glm::vec3& b = mesh.positions[mesh.indices[t + 1]];
        const glm::vec3& c = mesh.positions[mesh.indices[t + 2]];
        const glm::vec3 centroid = (a + b + c) / 3.0f;
        const glm::vec3 n = faceNormal(a, b, c);
        if (!(glm::dot(n, n) > 0.25f)) continue;  // degenerate triangle: no normal to show
        pushVertex(out, centroid);
        pushVertex(out, centroid, n);
    }
    return out;
}

void upload(gl::VertexArray& vao, gl::Buffer& vbo, const std::vector<float>& data, GLenum usage) {
    if (!vao) vao = gl::makeVertexArray();
    if (!vbo) vbo = gl::makeBuffer();
    glBindVertexArray(vao.get());
    glBindBuffer(GL_ARRAY_BUFFER, vbo.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), usage);
    const auto stride = GLsizei(kFloatsPerVertex * sizeof(float));
    glVertexAttribPointer(SL_ATTRIB_POSITION, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(0));
    glEnableVertexAttribArray(SL_ATTRIB_POSITION);
    glVertexAttribPointer(SL_ATTRIB_NORMAL, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(3 * sizeof(float)));
    glEnableVertexAttribArray(SL_ATTRIB_NORMAL);
    glBindVertexArray(0);
}

void copyMat(float (&dst)[16], const glm::mat4& m) { std::memcpy(dst, glm::value_ptr(m), sizeof dst); }

// drawLights' parts, one per kind of light. A directional light: a line from its handle along the
// direction the light travels; returns the handle, where the cross goes.
glm::vec3 pushDirectionMarker(std::vector<float>& data, const Light& light, const Camera& cam) {
    const glm::vec3 at = lightHandle(light, cam);
    pushVertex(data, at);
    pushVertex(data, at + glm::normalize(light.direction) * (0.4f * directionalHandleDistance(cam)));
    return at;
}

// A spot light: the axis and four lines along the outer cone, a quarter of the way to the eye long.
void pushSpotCone(std::vector<float>& data, const Light& light, const Camera& cam) {
    const glm::vec3 at = light.position;
    const glm::vec3 z = glm::normalize(light.direction);
    const glm::vec3 ref = std::fabs(z.y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 x = glm::normalize(glm::cross(ref, z)), y = glm::cross(z, x);
    const float length = 0.25f * std::max(glm::length(cam.eye - at), 1e-3f);
    const float spread = std::tan(glm::radians(std::min(light.outerConeDeg, 80.0f)));
    pushVertex(data, at);
    pushVertex(data, at + z * length);
    for (const glm::vec3& side : {x, -x, y, -y}) {
        pushVertex(data, at);
        pushVertex(data, at + (z + side * spread) * (length / std::sqrt(1.0f + spread * spread)));
    }
}

// An area light: the rectangle's outline, its emitting normal, and a dot per sample position.
void pushAreaOutline(std::vector<float>& data, const Light& light, const Camera& cam) {
    const glm::vec3 at = light.position;
    const AreaFrame f = areaFrame(light);
    const glm::vec3 c[4] = {at - 0.5f * f.u - 0.5f * f.v, at + 0.5f * f.u - 0.5f * f.v, at + 0.5f * f.u + 0.5f * f.v,
                            at - 0.5f * f.u + 0.5f * f.v};
    for (int k = 0; k < 4; ++k) {
        pushVertex(data, c[k]);
        pushVertex(data, c[(k + 1) % 4]);
    }
    const float extent = 0.5f * std::max(light.size.x, light.size.y);
    pushVertex(data, at);
    pushVertex(data, at + f.n * extent);
    const float tick = 0.01f * std::max(glm::length(cam.eye - at), 1e-3f);
    for (int j = 0; j < light.samples.y; ++j)
        for (int k = 0; k < light.samples.x; ++k) {
            const glm::vec3 p = areaSamplePosition(light, k, j);
            pushVertex(data, p - tick * glm::normalize(f.u));
            pushVertex(data, p + tick * glm::normalize(f.u));
        }
}

// A three-axis cross `half` long each way from `at`.
void pushCross(std::vector<float>& data, const glm::vec3& at, float half) {
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 d(0.0f);
        d[axis] = half;
        pushVertex(data, at - d);
        pushVertex(data, at + d);
    }
}

}  // namespace

OverlayRenderer::LineProgram OverlayRenderer::lineProgram(gl::Program program) {
    LineProgram p;
    p.normalLength = glGetUniformLocation(program.get(), "u_normalLength");
    p.depthBias = glGetUniformLocation(program.get(), "u_depthBias");
    p.tangentTips = glGetUniformLocation(program.get(), "u_tangentTips");
    p.color = glGetUniformLocation(program.get(), "u_overlayColor");
    p.viewportSize = glGetUniformLocation(program.get(), "u_viewportSize");
    p.lineWidth = glGetUniformLocation(program.get(), "u_lineWidth");
    p.program = std::move(program);
    return p;
}

const OverlayRenderer::LineProgram& OverlayRenderer::useWidth(float pixels) {
    const LineProgram& p = pixels > 1.01f ? wide_ : thin_;
    if (current_ != &p) {
        glUseProgram(p.program.get());
        // 3e-4 of NDC depth keeps edges in front of the triangles they bound with a 24-bit depth buffer
        // at the scene's usual near/far ratio (llvmpipe rasterises lines and triangles with different
        // depth rounding, so a bias of 0 leaves dashed lines).
        glUniform1f(p.depthBias, 3e-4f);
        current_ = &p;
    }
    if (&p == &wide_) {
        glUniform2f(p.viewportSize, paneWidth_, paneHeight_);
        glUniform1f(p.lineWidth, pixels);
    }
    return p;
}

OverlayRenderer::OverlayRenderer(const ShaderLibrary& shaders)
    : thin_(lineProgram(buildProgram("overlay", shaders))),
#if SHADELAB_GLES
      // WebGL2 has no geometry shaders: overlay lines are one pixel wide there (docs/web.md).
      wide_(lineProgram(buildProgram("overlay", shaders))) {
}
#else
      wide_(lineProgram(buildProgram("overlay", shaders, {}, "", "overlay_wide"))) {
}
#endif

void OverlayRenderer::setGeometry(std::shared_ptr<const SceneGeometry> geometry) {
    geometry_ = std::move(geometry);
    const std::size_t n = geometry_ ? geometry_->meshes.size() : 0;
    lines_.clear();
    lines_.resize(n);
    objectRadius_.assign(n, 1.0f);
    for (std::size_t i = 0; i < n; ++i) {
        float r2 = 0.0f;
        for (const glm::vec3& p : geometry_->meshes[i].positions) r2 = std::max(r2, glm::dot(p, p));
        if (r2 > 0.0f) objectRadius_[i] = std::sqrt(r2);
    }
}

const OverlayRenderer::Lines& OverlayRenderer::lines(std::size_t object, LineKind kind) {
    Lines& l = lines_[object][kind];
    if (l.vao) return l;
    const Mesh& mesh = geometry_->meshes[object];
    const std::vector<float> data = kind == Edges           ? edgeLines(mesh)
                                    : kind == VertexNormals ? vertexNormalLines(mesh)
                                    : kind == Tangents      ? tangentLines(mesh)
                                                            : faceNormalLines(mesh);
    upload(l.vao, l.vertices, data, GL_STATIC_DRAW);
    l.vertexCount = GLsizei(data.size() / kFloatsPerVertex);
    return l;
}

// A FrameBlock per pane, an ObjectBlock per object, then an identity ObjectBlock for the light markers
// (which are given in world space). Only the matrices are read.
void OverlayRenderer::stageMatrices(const Scene& scene, const std::vector<Pane>& panes, std::size_t objects) {
    uniforms_.begin(panes.size(), objects + 1);
    for (std::size_t p = 0; p < panes.size(); ++p) {
        gpu::FrameBlock b{};
        const float aspect = float(panes[p].width) / float(std::max(panes[p].height, 1));
        copyMat(b.clipFromWorld, clipFromView(scene.camera, aspect) * viewFromWorld(scene.camera));
        uniforms_.setFrame(p, b);
    }
    for (std::size_t o = 0; o <= objects; ++o) {
        gpu::ObjectBlock b{};
        const glm::mat4 world = o < objects ? worldFromObject(scene.objects[o].transform) : glm::mat4(1.0f);
        copyMat(b.worldFromObject, world);
        copyMat(b.normalWorldFromObject, glm::mat4(normalWorldFromObject(world)));
        uniforms_.setObject(o, b);
    }
    uniforms_.upload();
}

// Object o's wireframe, normals and tangents, as `options` asks, in the bound pane.
void OverlayRenderer::drawObjectLines(const Scene& scene, const OverlayOptions& options, std::size_t o) {
    uniforms_.bindObject(o);
    const glm::vec3 s = glm::abs(scene.objects[o].transform.scale);
    const float normalLength = options.normalScale * objectRadius_[o] * std::max({s.x, s.y, s.z});
    const std::pair<bool, LineKind> kinds[] = {{options.wireframe, Edges},
                                               {options.vertexNormals, VertexNormals},
                                               {options.faceNormals, FaceNormals},
                                               {options.tangents, Tangents}};
    for (const auto& [enabled, kind] : kinds) {
        if (!enabled) continue;
        // Wireframe: light grey, half covering; vertex normals cyan; face normals yellow (the
        // colours of the lecture's normal slides); tangents magenta.
        static const float kColors[kLineKinds][4] = {{0.92f, 0.92f, 0.92f, 0.55f},
                                                     {0.25f, 0.85f, 1.0f, 1.0f},
                                                     {1.0f, 0.85f, 0.2f, 1.0f},
                                                     {1.0f, 0.3f, 0.85f, 1.0f}};
        const Lines& l = lines(o, kind);
        if (l.vertexCount == 0) continue;
        const LineProgram& program = useWidth(std::max(1.0f, options.lineWidth * (kind == Edges ? 0.5f : 0.75f)));
        glUniform1f(program.normalLength, normalLength);
        glUniform1f(program.tangentTips, kind == Tangents ? 1.0f : 0.0f);
        glUniform4fv(program.color, 1, kColors[kind]);
        glBindVertexArray(l.vao.get());
        glDrawArrays(GL_LINES, 0, l.vertexCount);
    }
}

void OverlayRenderer::render(const Scene& scene, const RenderTarget& target, const OverlayOptions& options,
                             const std::vector<OverlayArrow>& arrows) {
    if (!options.any() && arrows.empty()) return;
    const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, target.width, target.height, scene.diff);
    const std::size_t objects = geometry_ ? std::min(geometry_->meshes.size(), scene.objects.size()) : 0;
    stageMatrices(scene, panes, objects);

    // Lines are tested against the surface's depth but do not write it, and blend so the shading shows
    // through the wireframe of a dense mesh.
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    current_ = nullptr;
    lineWidth_ = options.lineWidth;

    for (std::size_t p = 0; p < panes.size(); ++p) {
        const Pane& pane = panes[p];
        glViewport(pane.x, target.height - pane.y - pane.height, pane.width, pane.height);
        paneWidth_ = float(std::max(pane.width, 1));
        paneHeight_ = float(std::max(pane.height, 1));
        uniforms_.bindFrame(p);
        for (std::size_t o = 0; o < objects; ++o) drawObjectLines(scene, options, o);
        if (options.lightMarkers) drawLights(scene, objects);
        const int marked = options.sampleMarkersLight;
        if (marked >= 0 && std::size_t(marked) < scene.lights.size() &&
            scene.lights[std::size_t(marked)].type == LightType::Area)
            drawAreaSamples(scene, scene.lights[std::size_t(marked)], objects);
        if (!arrows.empty()) drawArrows(scene, pane, int(p), arrows, objects);
    }
    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
}

void OverlayRenderer::drawLights(const Scene& scene, std::size_t identityObject) {
    // A three-axis cross at each point light (a spot light: with its axis and outer cone); for a
    // directional light a cross up-light of the target and a line along the direction the light travels; for an area
    // light its rectangle, normal and sample positions around the cross at its centre. Sizes follow the distance to the
    // eye, so a marker stays the same size on screen wherever the light is.
    std::vector<float> data;
    std::vector<std::pair<GLint, glm::vec4>> draws;  // first vertex, colour
    const Camera& cam = scene.camera;
    for (std::size_t i = 0; i < scene.lights.size() && i < std::size_t(kMaxLights); ++i) {
        const Light& light = scene.lights[i];
        const GLint first = GLint(data.size() / kFloatsPerVertex);
        glm::vec3 at = light.position;
        if (light.type == LightType::Directional) at = pushDirectionMarker(data, light, cam);
        if (light.type == LightType::Spot) pushSpotCone(data, light, cam);
        if (light.type == LightType::Area) pushAreaOutline(data, light, cam);
        pushCross(data, at, 0.03f * std::max(glm::length(cam.eye - at), 1e-3f));
        // The light's colour brought to full brightness, so a dim or dark-coloured light still shows.
        const float peak = std::max({light.color.r, light.color.g, light.color.b});
        const glm::vec3 c = peak > 1e-3f ? light.color / peak : glm::vec3(1.0f);
        draws.emplace_back(first, glm::vec4(c, 1.0f));
    }
    drawWorldLines(data, draws, identityObject);
}

void OverlayRenderer::drawWorldLines(const std::vector<float>& data,
                                     const std::vector<std::pair<GLint, glm::vec4>>& runs, std::size_t identityObject) {
    if (runs.empty()) return;
    upload(worldLines_.vao, worldLines_.vertices, data, GL_STREAM_DRAW);
    uniforms_.bindObject(identityObject);
    const LineProgram& p = useWidth(lineWidth_);
    glUniform1f(p.normalLength, 0.0f);
    glUniform1f(p.tangentTips, 0.0f);
    glBindVertexArray(worldLines_.vao.get());
    for (std::size_t d = 0; d < runs.size(); ++d) {
        const GLint end = d + 1 < runs.size() ? runs[d + 1].first : GLint(data.size() / kFloatsPerVertex);
        glUniform4fv(p.color, 1, glm::value_ptr(runs[d].second));
        glDrawArrays(GL_LINES, runs[d].first, end - runs[d].first);
    }
}

void OverlayRenderer::drawAreaSamples(const Scene& scene, const Light& light, std::size_t identityObject) {
    // The rectangle, its nx x ny stratification cells (faint), and a small square with a cross at each
    // sample position: areaSamplePosition(), the positions the shaders light with, so the jitter inside
    // each cell is what the picture uses.
    std::vector<float> data;
    std::vector<std::pair<GLint, glm::vec4>> runs;
    const AreaFrame f = areaFrame(light);
    const glm::vec3 uUnit = glm::normalize(f.u), vUnit = glm::normalize(f.v);
    const glm::vec3 origin = light.position - 0.5f * f.u - 0.5f * f.v;  // corner (a, b) = (-0.5, -0.5)
    const float peak = std::max({light.color.r, light.color.g, light.color.b});
    const glm::vec3 color = peak > 1e-3f ? light.color / peak : glm::vec3(1.0f);
    runs.emplace_back(0, glm::vec4(color, 0.35f));
    for (int i = 1; i < light.samples.x; ++i) {
        const glm::vec3 p = origin + float(i) / float(light.samples.x) * f.u;
        pushVertex(data, p);
        pushVertex(data, p + f.v);
    }
    for (int j = 1; j < light.samples.y; ++j) {
        const glm::vec3 p = origin + float(j) / float(light.samples.y) * f.v;
        pushVertex(data, p);
        pushVertex(data, p + f.u);
    }
    runs.emplace_back(GLint(data.size() / kFloatsPerVertex), glm::vec4(color, 1.0f));
    const glm::vec3 corners[4] = {origin, origin + f.u, origin + f.u + f.v, origin + f.v};
    for (int k = 0; k < 4; ++k) {
        pushVertex(data, corners[k]);
        pushVertex(data, corners[(k + 1) % 4]);
    }
    // Squares about 12 pixels across at the light's distance (at 600 pixels of height and 45 degrees),
    // but never more than 40% of a cell, so neighbours stay apart.
    const float cell = std::min(light.size.x / float(light.samples.x), light.size.y / float(light.samples.y));
    const float half = std::min(0.008f * glm::length(scene.camera.eye - light.position), 0.2f * cell);
    for (int j = 0; j < light.samples.y; ++j)
        for (int i = 0; i < light.samples.x; ++i) {
            const glm::vec3 p = areaSamplePosition(light, i, j);
            const glm::vec3 c[4] = {p - half * uUnit - half * vUnit, p + half * uUnit - half * vUnit,
                                    p + half * uUnit + half * vUnit, p - half * uUnit + half * vUnit};
            for (int k = 0; k < 4; ++k) {
                pushVertex(data, c[k]);
                pushVertex(data, c[(k + 1) % 4]);
            }
            pushVertex(data, c[0]);
            pushVertex(data, c[2]);
            pushVertex(data, c[1]);
            pushVertex(data, c[3]);
        }
    drawWorldLines(data, runs, identityObject);
}

void OverlayRenderer::drawArrows(const Scene& scene, const Pane& pane, int paneIndex,
                                 const std::vector<OverlayArrow>& arrows, std::size_t identityObject) {
    std::vector<float> data;
    std::vector<std::pair<GLint, glm::vec4>> runs;
    const Camera& cam = scene.camera;
    // A pixel's world size per unit of distance from the eye, in this pane.
    const float pixelPerDistance = 2.0f * std::tan(glm::radians(cam.fovYDeg) * 0.5f) / float(std::max(pane.height, 1));
    for (const OverlayArrow& a : arrows) {
        if (a.pane >= 0 && a.pane != paneIndex) continue;
        runs.emplace_back(GLint(data.size() / kFloatsPerVertex), a.color);
        const float pixel = pixelPerDistance * std::max(glm::length(cam.eye - a.fromWorld), 1e-3f);
        const glm::vec3 d = a.toWorld - a.fromWorld;
        const float length = glm::length(d);
        if (length < 1e-6f) {  // a marker: a three-axis cross ~10 pixels across
            for (int axis = 0; axis < 3; ++axis) {
                glm::vec3 offset(0.0f);
                offset[axis] = 5.0f * pixel;
                pushVertex(data, a.fromWorld - offset);
                pushVertex(data, a.fromWorld + offset);
            }
            continue;
        }
        const glm::vec3 dir = d / length;
        // `side` is across the arrow as seen from the eye; `lift` completes the frame.
        glm::vec3 side = glm::cross(dir, cam.eye - a.fromWorld);
        if (glm::length(side) < 1e-6f)
            side = glm::cross(dir, std::fabs(dir.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0));
        side = glm::normalize(side);
        const glm::vec3 lift = glm::cross(side, dir);
        // Core-profile lines are one pixel wide: three side by side make a shaft that reads on a projector.
        for (float o : {-1.0f, 0.0f, 1.0f}) {
            pushVertex(data, a.fromWorld + o * pixel * side);
            pushVertex(data, a.toWorld + o * pixel * side);
        }
        // The head: four lines from the tip back to a ring around the shaft.
        const float head = std::min(0.25f * length, 16.0f * pixel);
        const glm::vec3 base = a.toWorld - head * dir;
        for (const glm::vec3& across : {side, -side, lift, -lift}) {
            pushVertex(data, a.toWorld);
            pushVertex(data, base + 0.45f * head * across);
        }
    }
    drawWorldLines(data, runs, identityObject);
}

}  // namespace shadelab
