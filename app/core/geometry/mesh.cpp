#include "core/geometry/mesh.hpp"

#include "core/shading/lighting.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace shadelab {

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    // Each component checked: std::max with a NaN in it can return a finite value.
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return fallback;
    const float largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    // Below ~1e-30 a float has lost most of its mantissa (denormals start at 1.2e-38).
    if (!(largest > 1e-30f)) return fallback;
    const glm::vec3 scaled = v / largest;  // largest component exactly 1: length in [1, sqrt 3]
    return scaled / glm::length(scaled);
}

glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 n = glm::cross(c - b, a - b);
    const float len = glm::length(n);
    return len > 0.0f ? n / len : glm::vec3(0.0f);
}

namespace {

// Makes every triangle counter-clockwise seen from the side its vertex normals point to. The
// generators below build their grids in whatever order is simplest and rely on this.
void orientToNormals(Mesh& m) {
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
        const glm::vec3 n = faceNormal(m.positions[a], m.positions[b], m.positions[c]);
        if (glm::dot(n, m.normals[a] + m.normals[b] + m.normals[c]) < 0.0f)
            std::swap(m.indices[t + 1], m.indices[t + 2]);
    }
}

// Two triangles for each cell of a grid of (rows + 1) x (columns + 1) vertices stored row by row (the
// torus's and the plane's); orientToNormals turns them to face their normals.
void appendGridTriangles(std::vector<uint32_t>& indices, int rows, int columns) {
    const int row = columns + 1;
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j) {
            const uint32_t a = uint32_t(i * row + j), b = a + uint32_t(row);
            indices.insert(indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
}

}  // namespace

Mesh makeUvSphere(int slices, int stacks, float radius) {
    Mesh m;
    const int row = slices + 1;
    m.positions.reserve(size_t(stacks + 1) * size_t(row));
    m.normals.reserve(m.positions.capacity());
    for (int i = 0; i <= stacks; ++i) {
        const double theta = glm::pi<double>() * i / stacks;  // 0 at the north pole (+y)
        for (int j = 0; j <= slices; ++j) {
            const double phi = 2.0 * glm::pi<double>() * j / slices;
            const glm::vec3 n(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                              float(std::sin(theta) * std::sin(phi)));
            m.normals.push_back(n);
            m.positions.push_back(radius * n);
        }
    }
    m.indices.reserve(size_t(slices) * size_t(stacks - 1) * 6);
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const uint32_t a = uint32_t(i * row + j), b = a + uint32_t(row);
            if (i != 0) m.indices.insert(m.indices.end(), {a, a + 1, b});
            if (i != stacks - 1) m.indices.insert(m.indices.end(), {a + 1, b + 1, b});
        }
    return m;
}

Mesh makeIcoSphere(int subdivisions, float radius) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> p = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (auto& v : p) v = glm::normalize(v);
    std::vector<uint32_t> idx = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                 6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto mid = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            p.push_back(glm::normalize(p[a] + p[b]));
            const auto i = uint32_t(p.size() - 1);
            midpoints.emplace(key, i);
            return i;
        };
        std::vector<uint32_t> next;
        next.reserve(idx.size() * 4);
        for (size_t k = 0; k < idx.size(); k += 3) {
            const uint32_t a = idx[k], b = idx[k + 1], c = idx[k + 2];
            const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        idx.swap(next);
    }
    Mesh m;
    m.normals = p;
    m.positions.reserve(p.size());
    for (const auto& n : p) m.positions.push_back(radius * n);
    m.indices = std::move(idx);
    orientToNormals(m);
    return m;
}

Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments) {
    Mesh m;
    for (int i = 0; i <= majorSegments; ++i) {
        const float u = 2.0f * glm::pi<float>() * float(i) / float(majorSegments);
        const glm::vec3 ring(std::cos(u), 0.0f, std::sin(u));
        for (int j = 0; j <= minorSegments; ++j) {
            const float v = 2.0f * glm::pi<float>() * float(j) / float(minorSegments);
            const glm::vec3 n = std::cos(v) * ring + std::sin(v) * glm::vec3(0, 1, 0);
            m.normals.push_back(n);
            m.positions.push_back(majorRadius * ring + minorRadius * n);
        }
    }
    appendGridTriangles(m.indices, majorSegments, minorSegments);
    orientToNormals(m);
    return m;
}

Mesh makeCube(float size) {
    Mesh m;
    const float h = size / 2.0f;
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {1.0f, -1.0f}) {
            const glm::vec3 n = sign * axes[axis];
            const glm::vec3 u = axes[(axis + 1) % 3], v = axes[(axis + 2) % 3];
            const auto base = uint32_t(m.positions.size());
            for (const auto& corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                m.positions.push_back(h * (n + corner.x * u + corner.y * v));
                m.normals.push_back(n);
            }
            m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    orientToNormals(m);
    return m;
}

Mesh makePlane(float size, int subdivisions) {
    Mesh m;
    for (int i = 0; i <= subdivisions; ++i)
        for (int j = 0; j <= subdivisions; ++j) {
            m.positions.push_back(
                {size * (float(j) / float(subdivisions) - 0.5f), 0.0f, size * (float(i) / float(subdivisions) - 0.5f)});
            m.normals.push_back({0.0f, 1.0f, 0.0f});
        }
    appendGridTriangles(m.indices, subdivisions, subdivisions);
    orientToNormals(m);
    return m;
}

Mesh makeProceduralMesh(const MeshSpec& s) {
    Mesh m;
    switch (s.type) {
    case MeshSpec::Type::UvSphere: m = makeUvSphere(s.slices, s.stacks, s.radius); break;
    case MeshSpec::Type::IcoSphere: m = makeIcoSphere(s.subdivisions, s.radius); break;
    case MeshSpec::Type::Torus: m = makeTorus(s.majorRadius, s.minorRadius, s.majorSegments, s.minorSegments); break;
    case MeshSpec::Type::Cube: m = makeCube(s.size); break;
    case MeshSpec::Type::Plane: m = makePlane(s.size, s.planeSubdivisions); break;
    case MeshSpec::Type::Gltf: break;
    }
    completeTangents(m);  // no texture coordinates: around the up axis
    return m;
}

TangentSource completeTangents(Mesh& m) {
    const std::size_t n = m.positions.size();
    if (m.tangents.size() != n) m.tangents.assign(n, glm::vec4(0.0f));
    bool missing = false;
    for (const glm::vec4& t : m.tangents) missing = missing || t.w == 0.0f;
    if (!missing) return TangentSource::Given;
    TangentSource source = TangentSource::UpAxis;
    std::vector<glm::vec3> tu, tv;  // per vertex: the sums of dP/du and dP/dv of its triangles
    if (m.variesColor()) {
        tu.assign(n, glm::vec3(0.0f));
        tv.assign(n, glm::vec3(0.0f));
        for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            const std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
            const glm::vec3 e1 = m.positions[b] - m.positions[a], e2 = m.positions[c] - m.positions[a];
            const glm::vec2 d1 = m.texcoords[b] - m.texcoords[a], d2 = m.texcoords[c] - m.texcoords[a];
            const float det = d1.x * d2.y - d2.x * d1.y;
            if (!(std::fabs(det) > 1e-12f)) continue;  // no texture-space area: no direction to take
            const glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) / det, dpdv = (e2 * d1.x - e1 * d2.x) / det;
            for (std::uint32_t v : {a, b, c}) {
                tu[v] += dpdu;
                tv[v] += dpdv;
            }
        }
    }
    for (std::size_t v = 0; v < n; ++v) {
        glm::vec4& out = m.tangents[v];
        if (out.w != 0.0f) continue;
        const glm::vec3& nrm = m.normals[v];
        const glm::vec4 up = tangentAroundUp(nrm);
        out = up;
        if (tu.empty()) continue;
        const glm::vec3 t = orthogonalTangent(tu[v], nrm, glm::vec3(0.0f));
        if (t == glm::vec3(0.0f)) continue;
        out = glm::vec4(t, glm::dot(glm::cross(nrm, t), tv[v]) < 0.0f ? -1.0f : 1.0f);
        source = TangentSource::Texcoords;
    }
    return source;
}

const char* toString(TangentSource s) {
    switch (s) {
    case TangentSource::Given: return "tangent";
    case TangentSource::Texcoords: return "texcoords";
    case TangentSource::UpAxis: return "up-axis";
    }
    return "up-axis";
}

glm::vec4 faceTangent(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, const glm::vec3& faceNrm) {
    const glm::vec3 sum = glm::vec3(a) + glm::vec3(b) + glm::vec3(c);
    return glm::vec4(orthogonalTangent(sum, faceNrm, glm::vec3(tangentAroundUp(faceNrm))), c.w);
}

FlatMesh makeFlatMesh(const Mesh& m) {
    FlatMesh f;
    const size_t vertexCount = m.positions.size(), triangles = m.triangleCount();
    f.positions = m.positions;
    f.normals = m.normals;
    f.centroids = m.positions;
    f.texcoords = m.texcoords;
    f.colors = m.colors;
    f.emissiveTexcoords = m.emissiveTexcoords;
    const bool tangents = m.tangents.size() == m.positions.size();
    if (tangents) f.tangents = m.tangents;
    f.indices.resize(m.indices.size());
    std::vector<bool> claimed(vertexCount, false);
    for (size_t t = 0; t < triangles; ++t) {
        uint32_t corner[3] = {m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]};
        const glm::vec3 n = faceNormal(m.positions[corner[0]], m.positions[corner[1]], m.positions[corner[2]]);
        const glm::vec3 centroid = (m.positions[corner[0]] + m.positions[corner[1]] + m.positions[corner[2]]) / 3.0f;
        // Rotate (a, b, c) -> (b, c, a) -> (c, a, b) until the last corner is free: same winding.
        int rotations = 0;
        while (rotations < 3 && claimed[corner[2]]) {
            std::rotate(corner, corner + 1, corner + 3);
            ++rotations;
        }
        uint32_t provoking = corner[2];
        const glm::vec4 tangent =
            tangents ? faceTangent(m.tangents[corner[0]], m.tangents[corner[1]], m.tangents[corner[2]], n)
                     : glm::vec4(0.0f);
        if (rotations == 3) {  // all three corners already provoke other triangles: a vertex of its own
            provoking = uint32_t(f.positions.size());
            f.positions.push_back(m.positions[corner[2]]);
            f.normals.push_back(n);
            f.centroids.push_back(centroid);
            if (tangents) f.tangents.push_back(tangent);
            if (m.variesColor()) {
                f.texcoords.push_back(m.texcoords[corner[2]]);
                f.colors.push_back(m.colors[corner[2]]);
                if (m.hasEmissiveTexture()) f.emissiveTexcoords.push_back(m.emissiveTexcoords[corner[2]]);
            }
        } else {
            claimed[provoking] = true;
            f.normals[provoking] = n;
            f.centroids[provoking] = centroid;
            if (tangents) f.tangents[provoking] = tangent;
        }
        f.indices[3 * t] = corner[0];
        f.indices[3 * t + 1] = corner[1];
        f.indices[3 * t + 2] = provoking;
    }
    return f;
}

namespace {

// The sRGB transfer function's inverse for each 8-bit value (as GL decodes an SRGB8_ALPHA8 texel).
const std::array<float, 256>& srgbDecodeTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            t[std::size_t(i)] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return t;
    }();
    return table;
}

// Texel index i of `size` under a wrap mode (GL's REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE).
int wrapTexel(int i, int size, int wrap) {
    if (wrap == 0x812F) return std::clamp(i, 0, size - 1);  // GL_CLAMP_TO_EDGE
    if (wrap == 0x8370) {                                   // GL_MIRRORED_REPEAT
        const int period = 2 * size;
        int m = ((i % period) + period) % period;
        return m < size ? m : period - 1 - m;
    }
    return ((i % size) + size) % size;  // GL_REPEAT
}

}  // namespace

glm::vec4 sampleTextureRgba(const TextureImage& t, const glm::vec2& uv) {
    if (t.width <= 0 || t.height <= 0) return glm::vec4(1.0f);
    const auto& decode = srgbDecodeTable();
    const auto texel = [&](int x, int y) {
        x = wrapTexel(x, t.width, t.wrapS);
        y = wrapTexel(y, t.height, t.wrapT);
        const std::uint8_t* p = &t.rgba[(std::size_t(y) * std::size_t(t.width) + std::size_t(x)) * 4];
        return glm::vec4(decode[p[0]], decode[p[1]], decode[p[2]], float(p[3]) / 255.0f);
    };
    // GL's texel space: texel centres at (i + 0.5) / size. Coordinates past a billion texels (a file
    // can hold any float) are taken as 0: no int holds them, and no float there has a fraction left.
    float x = uv.x * float(t.width), y = uv.y * float(t.height);
    if (!(std::fabs(x) < 1e9f)) x = 0.0f;
    if (!(std::fabs(y) < 1e9f)) y = 0.0f;
    if (t.magFilter == 0x2600)  // GL_NEAREST
        return texel(int(std::floor(x)), int(std::floor(y)));
    const float fx = x - 0.5f, fy = y - 0.5f;
    const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    const float ax = fx - float(x0), ay = fy - float(y0);
    return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), ax),
                    glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), ax), ay);
}

glm::vec3 sampleTexture(const TextureImage& t, const glm::vec2& uv) { return glm::vec3(sampleTextureRgba(t, uv)); }

BoundingSphere worldBounds(const std::vector<const Mesh*>& meshes, const std::vector<glm::mat4>& worldFromObject) {
    // World positions of every mesh (no copy for the common untransformed mesh).
    auto forEachWorldPosition = [&](auto&& visit) {
        for (size_t i = 0; i < meshes.size(); ++i) {
            const glm::mat4& m = worldFromObject[i];
            if (m == glm::mat4(1.0f)) {
                for (const glm::vec3& p : meshes[i]->positions) visit(p);
            } else {
                for (const glm::vec3& p : meshes[i]->positions) visit(glm::vec3(m * glm::vec4(p, 1.0f)));
            }
        }
    };
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    bool any = false;
    forEachWorldPosition([&](const glm::vec3& w) {
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
        any = true;
    });
    BoundingSphere b;
    if (!any) return b;
    b.center = 0.5f * (lo + hi);
    float radius2 = 0.0f;
    forEachWorldPosition(
        [&](const glm::vec3& w) { radius2 = std::max(radius2, glm::dot(w - b.center, w - b.center)); });
    b.radius = std::sqrt(radius2);
    return b;
}

}  // namespace shadelab
