#include "core/probe/probe.hpp"

#include "core/shading/environment.hpp"

#include "core/base/error.hpp"
#include "core/geometry/mesh.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace shadelab {
namespace {

// Start shadow rays this far (relative to the scene's size) off the surface along N, so a point
// does not hide itself behind its own triangle in float rounding.
constexpr float kShadowRayOffset = 1e-4f;

// What one mode's evaluations need to know about the probed triangle.
struct TriangleContext {
    const Scene& scene;
    const LightingEnvironment& env;
    const Material& material;  // C as drawn at the point: the part's base colour times the texel
    const SceneRayCaster& caster;
    glm::mat4 worldFromObject;
    glm::mat3 normalWorldFromObject;
    glm::vec3 posObject[3];
    glm::vec3 nrmObject[3];
    glm::vec4 tanObject[3];  // Mesh::tangents (xyz, w the handedness)
    std::uint32_t vertex[3];
    glm::vec3 barycentric;
    float facing = 1.0f;  // -1: the back of a double-sided part, where every normal is flipped (glTF)
    // Where C varies (SL_TEXTURED): the material with the base colour alone, and the texel (texture x
    // vertex colour) the fragment multiplies it by. Flat and Gouraud evaluate with the former and
    // combine per fragment as shaders/object_color.glsl does; Phong evaluates with `material`.
    const Material* baseMaterial = nullptr;
    glm::vec3 texel{1.0f};
    glm::vec3 emission{0.0f};  // textured: E at the point, which the fragment adds (combineTerms)
};

// Of what `show` selects, the part the texel does not multiply: the specular.
glm::vec3 shownSpecular(const ShadingTerms& t, const TermView& show) {
    switch (show.term) {
    case ShowTerm::All: return t.specular + t.environment;  // mirror and glass: C does not colour them either
    case ShowTerm::Specular: return t.specular;
    case ShowTerm::Light:
        return show.light >= 0 && std::size_t(show.light) < t.lights.size() ? t.lights[std::size_t(show.light)].specular
                                                                            : glm::vec3(0.0f);
    default: return glm::vec3(0.0f);
    }
}

// E as the textured flat and Gouraud fragment adds it (object_color.glsl, combineTerms): where `show` keeps it.
glm::vec3 shownEmission(const TriangleContext& c) {
    const ShowTerm t = c.scene.show.term;
    return t == ShowTerm::All || t == ShowTerm::Emissive ? c.emission : glm::vec3(0.0f);
}

// The formula at one point with one unit normal: shadeTerms with, when shadows are on, an occlusion
// test by ray cast; then the lecture's vectors for each light.
// `tanWorld`: the tangent there (xyz in world space, any length; w the handedness).
ProbeEvaluation evaluate(const TriangleContext& c, const Material& material, const glm::vec3& posWorld,
                         const glm::vec3& nrmWorld, const glm::vec4& tanWorld) {
    ProbeEvaluation e;
    e.posWorld = posWorld;
    e.nrmWorld = nrmWorld;
    e.anisotropic = anisotropicLobe(material, c.env);
    e.frame = tangentFrame(nrmWorld, glm::vec3(tanWorld), tanWorld.w);
    e.viewWorld = glm::normalize(c.env.eyeWorld - posWorld);
    const std::size_t lightCount = c.env.lights.size();
    e.lights.resize(lightCount);
    Visibility visibility;
    if (c.scene.shadows.enabled) {
        const float offset = kShadowRayOffset * std::max(c.caster.radius(), 1e-3f);
        // `offset` by value: the lambda outlives this block (shadeTerms calls it below).
        visibility = [&, offset](const glm::vec3& p, const LightRay& ray) {
            ProbeLight& light = e.lights[ray.light];
            ++light.samplesTested;
            const bool hidden = c.caster.occluded(p + offset * nrmWorld, ray.towardLight, 0.0f, ray.distance - offset);
            if (!hidden) ++light.samplesVisible;
            return hidden ? 0.0f : 1.0f;
        };
    }
    e.terms = shadeTerms(material, c.env, posWorld, nrmWorld, visibility, &e.frame);
    e.mirrorGlass = mirrorOrGlass(material, c.env.environment);
    if (e.mirrorGlass) e.environment = environmentTerm(material, c.env, nrmWorld, e.viewWorld);
    for (std::size_t l = 0; l < lightCount; ++l) {
        const Light& light = c.env.lights[l];
        ProbeLight& out = e.lights[l];
        out.towardLight = light.type == LightType::Directional ? glm::normalize(-light.direction)
                                                               : glm::normalize(light.position - posWorld);
        out.nDotI = glm::dot(nrmWorld, out.towardLight);
        out.reflected = 2.0f * out.nDotI * nrmWorld - out.towardLight;
        out.rDotV = glm::dot(out.reflected, e.viewWorld);
        out.halfway = glm::normalize(out.towardLight + e.viewWorld);
        out.hDotN = glm::dot(out.halfway, nrmWorld);
        out.exponent = e.anisotropic ? anisotropicExponent(material.anisotropy, out.halfway, e.frame) : material.ke;
        out.diffuse = e.terms.lights[l].diffuse;
        out.specular = e.terms.lights[l].specular;
        out.visibility = out.samplesTested > 0 ? float(out.samplesVisible) / float(out.samplesTested) : 1.0f;
    }
    return e;
}

glm::vec3 toWorld(const glm::mat4& m, const glm::vec3& p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }
// A tangent to world space as the shaders take it (tangentToWorld: the transform itself), w kept.
glm::vec4 tangentToWorld(const glm::mat4& m, const glm::vec4& t) { return glm::vec4(glm::mat3(m) * glm::vec3(t), t.w); }

// Phong: phong.vert passes normalWorldFromObject * normal unnormalised; phong.frag normalises the
// interpolated vector. The tangent goes to world space; the rasteriser interpolates all four components.
void evaluatePhong(const TriangleContext& c, const Material& lit, ModeProbe& m) {
    const glm::vec3& w = c.barycentric;
    const glm::vec3 posObject = w.x * c.posObject[0] + w.y * c.posObject[1] + w.z * c.posObject[2];
    const glm::vec3 nrm = w.x * (c.normalWorldFromObject * c.nrmObject[0]) +
                          w.y * (c.normalWorldFromObject * c.nrmObject[1]) +
                          w.z * (c.normalWorldFromObject * c.nrmObject[2]);
    const glm::vec4 tan = w.x * tangentToWorld(c.worldFromObject, c.tanObject[0]) +
                          w.y * tangentToWorld(c.worldFromObject, c.tanObject[1]) +
                          w.z * tangentToWorld(c.worldFromObject, c.tanObject[2]);
    m.evaluations.push_back(
        evaluate(c, lit, toWorld(c.worldFromObject, posObject), c.facing * glm::normalize(nrm), tan));
    m.color = m.evaluations[0].terms.total;
}

// Gouraud: at the three vertices, interpolated. Textured: gouraud.vert's two parts, unclamped,
// interpolated; combined in gouraud.frag.
void evaluateGouraud(const TriangleContext& c, const Material& lit, ModeProbe& m) {
    const glm::vec3& w = c.barycentric;
    glm::vec3 termsOfC(0.0f), specular(0.0f);
    for (int k = 0; k < 3; ++k) {
        ProbeEvaluation e = evaluate(c, lit, toWorld(c.worldFromObject, c.posObject[k]),
                                     c.facing * glm::normalize(c.normalWorldFromObject * c.nrmObject[k]),
                                     tangentToWorld(c.worldFromObject, c.tanObject[k]));
        e.site = ProbeEvaluation::Site::Vertex;
        e.vertex = c.vertex[k];
        m.color += w[k] * e.terms.total;
        const glm::vec3 s = shownSpecular(e.terms, c.scene.show);
        termsOfC += w[k] * (e.terms.shown - s);
        specular += w[k] * s;
        m.evaluations.push_back(std::move(e));
    }
    if (c.baseMaterial) m.color = glm::clamp(c.texel * termsOfC + specular + shownEmission(c), 0.0f, 1.0f);
}

// Flat: as makeFlatMesh, the face normal of the corners in index order and the object-space centroid,
// both taken to world space by flat.vert.
void evaluateFlat(const TriangleContext& c, const Material& lit, ModeProbe& m) {
    const glm::vec3 centroid = (c.posObject[0] + c.posObject[1] + c.posObject[2]) / 3.0f;
    const glm::vec3 face = faceNormal(c.posObject[0], c.posObject[1], c.posObject[2]);
    const glm::vec4 tan = faceTangent(c.tanObject[0], c.tanObject[1], c.tanObject[2], face);
    ProbeEvaluation e =
        evaluate(c, lit, toWorld(c.worldFromObject, centroid),
                 c.facing * glm::normalize(c.normalWorldFromObject * face), tangentToWorld(c.worldFromObject, tan));
    e.site = ProbeEvaluation::Site::Centroid;
    m.color = e.terms.total;
    if (c.baseMaterial) {
        const glm::vec3 s = shownSpecular(e.terms, c.scene.show);
        m.color = glm::clamp(c.texel * (e.terms.shown - s) + s + shownEmission(c), 0.0f, 1.0f);
    }
    m.evaluations.push_back(std::move(e));
}

ModeProbe evaluateMode(const TriangleContext& c, ShadingMode mode) {
    ModeProbe m;
    m.mode = mode;
    // Phong evaluates with the sampled C; flat and Gouraud with the base colour (see TriangleContext).
    const Material& lit = mode != ShadingMode::Phong && c.baseMaterial ? *c.baseMaterial : c.material;
    switch (mode) {
    case ShadingMode::Phong: evaluatePhong(c, lit, m); break;
    case ShadingMode::Gouraud: evaluateGouraud(c, lit, m); break;
    case ShadingMode::Flat: evaluateFlat(c, lit, m); break;
    }
    m.output = m.color;
    if (c.scene.outputEncoding == OutputEncoding::Srgb)
        m.output = glm::vec3(encodeSrgb(m.color.x), encodeSrgb(m.color.y), encodeSrgb(m.color.z));
    // UNORM8 framebuffers store round(value * 255).
    for (int k = 0; k < 3; ++k) m.output8[k] = int(std::lround(glm::clamp(m.output[k], 0.0f, 1.0f) * 255.0f));
    return m;
}

glm::ivec3 quantize(const glm::vec3& c) {
    glm::ivec3 q;
    for (int k = 0; k < 3; ++k) q[k] = int(std::lround(glm::clamp(c[k], 0.0f, 1.0f) * 255.0f));
    return q;
}

// The part of the mesh a triangle belongs to (nullptr for a mesh without parts).
const MeshPart* partOf(const Mesh& mesh, std::size_t triangle) {
    const std::size_t index = 3 * triangle;
    for (const MeshPart& part : mesh.parts)
        if (index >= part.firstIndex && index < std::size_t(part.firstIndex) + part.indexCount) return &part;
    return nullptr;
}

// Whether the eye sees the back of the triangle: its face normal (to world space as normals go,
// so a mirroring transform keeps the outside) points away from the eye. For a planar triangle this
// is the rasteriser's gl_FrontFacing, wherever on the triangle it is asked.
bool seenFromBehind(const TriangleContext& c, const glm::vec3& eyeWorld) {
    const glm::vec3 face = c.normalWorldFromObject * faceNormal(c.posObject[0], c.posObject[1], c.posObject[2]);
    const glm::vec3 centroid = toWorld(c.worldFromObject, (c.posObject[0] + c.posObject[1] + c.posObject[2]) / 3.0f);
    return glm::dot(face, eyeWorld - centroid) < 0.0f;
}

// The material the renderer draws a triangle with: a glTF part's base colour unless the scene set one.
Material drawnMaterial(const Scene& scene, const Mesh& mesh, std::size_t object, std::size_t triangle) {
    Material m = scene.objects[object].material;
    if (m.colorSet) return m;
    const MeshPart* part = partOf(mesh, triangle);
    if (part && part->hasBaseColor) m.color = part->baseColor;
    if (part) m.emissive = part->emissive;
    return m;
}

// Where C varies, the sampled C: the base colour times the texture and the vertex colour at the point
// (object_color.glsl), with the coordinates and colours interpolated by the barycentrics `w`; E times
// the emissive texture there. Flat and Gouraud then evaluate with `baseMaterial` (E left out, added per
// fragment) and multiply by the texel.
void sampleColor(const Mesh& mesh, const MeshPart* part, const glm::vec3& w, ProbeResult& r, TriangleContext& c,
                 Material& baseMaterial) {
    r.textured = true;
    r.texcoord =
        w.x * mesh.texcoords[c.vertex[0]] + w.y * mesh.texcoords[c.vertex[1]] + w.z * mesh.texcoords[c.vertex[2]];
    const glm::vec4 color =
        w.x * mesh.colors[c.vertex[0]] + w.y * mesh.colors[c.vertex[1]] + w.z * mesh.colors[c.vertex[2]];
    glm::vec4 texel = color;
    if (part && part->texture >= 0 && std::size_t(part->texture) < mesh.textures.size())
        texel *= sampleTextureRgba(*mesh.textures[std::size_t(part->texture)], r.texcoord);
    r.texel = glm::vec3(texel);
    r.alpha *= texel.a;
    r.baseColor = baseMaterial.color;
    r.material.color = baseMaterial.color * r.texel;
    // E varies with the emissive texture: Phong's sum has it at the point, flat and Gouraud add it per fragment.
    if (part && part->emissiveTexture >= 0 && mesh.hasEmissiveTexture() &&
        std::size_t(part->emissiveTexture) < mesh.textures.size()) {
        const glm::vec2 uv = w.x * mesh.emissiveTexcoords[c.vertex[0]] + w.y * mesh.emissiveTexcoords[c.vertex[1]] +
                             w.z * mesh.emissiveTexcoords[c.vertex[2]];
        r.material.emissive *= sampleTexture(*mesh.textures[std::size_t(part->emissiveTexture)], uv);
    }
    c.emission = r.material.emissive;
    baseMaterial.emissive = glm::vec3(0.0f);
    c.baseMaterial = &baseMaterial;
    c.texel = r.texel;
}

}  // namespace

void checkProbePixel(const Scene& scene, int x, int y, const std::string& flag) {
    if (x < 0 || y < 0 || x >= scene.width || y >= scene.height)
        throw InputError(flag + ": pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                         std::to_string(scene.width) + "x" + std::to_string(scene.height) + " image");
}

bool validAnchor(const Scene& scene, const SceneGeometry& geometry, const ProbeAnchor& a) {
    return a.object < scene.objects.size() && a.object < geometry.meshes.size() &&
           a.triangle < geometry.meshes[a.object].triangleCount();
}

ProbeResult probeAnchor(const Scene& scene, const SceneGeometry& geometry, const SceneRayCaster& caster,
                        const ProbeAnchor& anchor) {
    ProbeResult r;
    const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff);
    r.x = anchor.x;
    r.y = anchor.y;
    r.pane = std::clamp(anchor.pane, 0, int(panes.size()) - 1);
    r.paneRect = panes[std::size_t(r.pane)];
    r.anchor = anchor;
    r.anchor.pane = r.pane;
    const Mesh& mesh = geometry.meshes[anchor.object];
    r.material = drawnMaterial(scene, mesh, anchor.object, anchor.triangle);
    Material baseMaterial = r.material;
    const MeshPart* triangles = partOf(mesh, anchor.triangle);
    // The glTF material's alpha and E: none where the scene's colour replaces it (Renderer::partDraw).
    const MeshPart* part = scene.objects[anchor.object].material.colorSet ? nullptr : triangles;
    if (part) {
        r.alphaMode = part->alphaMode;
        r.alpha = part->baseAlpha;
        r.alphaCutoff = part->alphaCutoff;
    }
    const LightingEnvironment env = lightingEnvironment(scene);
    const glm::mat4 world = worldFromObject(scene.objects[anchor.object].transform);
    TriangleContext c{scene, env, r.material,        caster, world, normalWorldFromObject(world), {}, {},
                      {},    {},  anchor.barycentric};
    for (int k = 0; k < 3; ++k) {
        c.vertex[k] = mesh.indices[3 * anchor.triangle + std::size_t(k)];
        c.posObject[k] = mesh.positions[c.vertex[k]];
        c.nrmObject[k] = mesh.normals[c.vertex[k]];
        c.tanObject[k] =
            c.vertex[k] < mesh.tangents.size() ? mesh.tangents[c.vertex[k]] : tangentAroundUp(c.nrmObject[k]);
    }
    // A double-sided part seen from behind is lit with its normals flipped; a single-sided one is
    // culled there (the ray cast does not find it), so its facing is not asked.
    r.doubleSided = triangles && triangles->doubleSided;
    r.backFace = r.doubleSided && seenFromBehind(c, scene.camera.eye);
    c.facing = r.backFace ? -1.0f : 1.0f;
    // Where C varies, the sampled C (and E): flat and Gouraud evaluate with the base material.
    if (mesh.variesColor() && scene.textures && !scene.objects[anchor.object].material.colorSet)
        sampleColor(mesh, part, anchor.barycentric, r, c, baseMaterial);
    r.posWorld = toWorld(world, anchor.barycentric.x * c.posObject[0] + anchor.barycentric.y * c.posObject[1] +
                                    anchor.barycentric.z * c.posObject[2]);
    r.miss = false;
    if (r.paneRect.difference) {
        // difference.frag: |a - b| * factor of the two panes' 8-bit values, clamped.
        r.modes = {evaluateMode(c, scene.diff.a), evaluateMode(c, scene.diff.b)};
        const glm::vec3 d = glm::abs(glm::vec3(r.modes[0].output8 - r.modes[1].output8)) / 255.0f * scene.diff.factor;
        r.output8 = quantize(d);
    } else {
        r.modes = {evaluateMode(c, r.paneRect.mode)};
        r.output8 = r.modes[0].output8;
    }
    return r;
}

ProbeResult probePixel(const Scene& scene, const SceneGeometry& geometry, const SceneRayCaster& caster, int x, int y) {
    checkProbePixel(scene, x, y, "probe");
    ProbeResult r;
    r.x = x;
    r.y = y;
    // The background is the clear colour, written as given; the difference of two backgrounds is 0.
    r.output8 = quantize(scene.background);
    const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff);
    for (std::size_t p = 0; p < panes.size(); ++p) {
        const Pane& pane = panes[p];
        if (x >= pane.x && x < pane.x + pane.width && y >= pane.y && y < pane.y + pane.height) r.pane = int(p);
    }
    if (r.pane < 0) return r;
    r.paneRect = panes[std::size_t(r.pane)];
    if (r.paneRect.difference) r.output8 = glm::ivec3(0);
    const Camera& cam = scene.camera;
    const glm::vec3 direction = pixelDirectionWorld(cam, r.paneRect, float(x) + 0.5f, float(y) + 0.5f);
    // The rasteriser keeps what lies between the near and far planes (depth along the view axis).
    const float along = glm::dot(direction, glm::normalize(cam.target - cam.eye));
    if (!(along > 0.0f)) return r;
    const auto hit = caster.nearestFrontFace(cam.eye, direction, cam.nearPlane / along, cam.farPlane / along);
    if (!hit || !validAnchor(scene, geometry, ProbeAnchor{x, y, r.pane, hit->object, hit->triangle, hit->barycentric}))
        return r;
    return probeAnchor(scene, geometry, caster,
                       ProbeAnchor{x, y, r.pane, hit->object, hit->triangle, hit->barycentric});
}

std::string probedPlace(const ProbeResult& result) {
    std::string mode = result.modes.empty() ? "" : toString(result.modes[0].mode);
    if (!mode.empty()) mode[0] = char(std::toupper(static_cast<unsigned char>(mode[0])));
    return "at pixel " + std::to_string(result.x) + "," + std::to_string(result.y) +
           (mode.empty() ? "" : " (" + mode + ")");
}

std::optional<ShadingTerms> probedTerms(const ProbeResult& result) {
    if (result.miss || result.modes.empty() || result.modes[0].evaluations.empty()) return std::nullopt;
    const ModeProbe& m = result.modes[0];
    ShadingTerms t;
    if (m.evaluations.size() == 1) {
        t = m.evaluations[0].terms;
    } else {
        for (std::size_t k = 0; k < m.evaluations.size() && k < 3; ++k) {
            const ShadingTerms& e = m.evaluations[k].terms;
            const float w = result.anchor.barycentric[int(k)];
            t.ambient += w * e.ambient;
            t.diffuse += w * e.diffuse;
            t.specular += w * e.specular;
            t.shown += w * e.shown;
            t.environment += w * e.environment;
        }
    }
    t.total = m.color;
    return t;
}

}  // namespace shadelab
