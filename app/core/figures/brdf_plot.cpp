// The BRDF as a function: the 3-D lobe and the heat maps of the isotropic
// parameterisation, both from core/shading's brdf() (see plot.hpp).
#include "core/figures/plot.hpp"
#include "core/figures/plot_parts.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadelab {
namespace {

using namespace plot_parts;

// The mesh lines, dimmer than the curves so the plane-of-incidence cut and the arrows stand out.
constexpr Rgba8 kRingColor{190, 140, 50, 255};
constexpr Rgba8 kMeridianColor{70, 140, 185, 255};

// "Blinn-Phong k_e = 32", "anisotropic k_t = 8, k_b = 256": the lobe in use.
std::string lobeName(const Material& m, const LightingEnvironment& env) {
    if (anisotropicLobe(m, env))
        return "anisotropic Blinn-Phong k_t = " + shortNumber(m.anisotropy.x) +
               ", k_b = " + shortNumber(m.anisotropy.y);
    return std::string(env.model == ReflectionModel::Phong ? "Phong" : "Blinn-Phong") + " k_e = " + shortNumber(m.ke);
}

float fr(const Material& m, const LightingEnvironment& env, const glm::vec3& i, const glm::vec3& v) {
    static const glm::vec3 n(0.0f, 1.0f, 0.0f);
    return brdf(m, env, n, i, v, plotTangentFrame()).total();
}

}  // namespace

glm::vec3 directionAt(float thetaDeg, float phiDeg) {
    const float t = glm::radians(thetaDeg), p = glm::radians(phiDeg);
    return {std::sin(t) * std::cos(p), std::cos(t), -std::sin(t) * std::sin(p)};
}

TangentFrame plotTangentFrame() { return TangentFrame{glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f)}; }

// ---- The 3-D lobe

LobeSurface sampleLobeSurface(const Material& m, const LightingEnvironment& env, float incidenceDeg) {
    return sampleLobeSurface(m, env, directionAt(incidenceDeg, 180.0f));
}

namespace {

// The lobe's half width at half its height: Phong's cos^k falls to 1/2 at acos(2^(-1/k)) from R;
// Blinn-Phong's spans about twice that in V. The narrower exponent of an anisotropic lobe.
float lobeHalfWidthDeg(const Material& m, const LightingEnvironment& env) {
    const float k = anisotropicLobe(m, env) ? std::min(m.anisotropy.x, m.anisotropy.y) : m.ke;
    return std::min(60.0f, (env.model == ReflectionModel::Phong ? 1.0f : 2.0f) *
                               glm::degrees(std::acos(std::pow(0.5f, 1.0f / std::max(k, 1e-3f)))));
}

// The grid around R: d(alpha, beta) = cos alpha R + sin alpha (cos beta b1 + sin beta b2), b1 in the
// surface across the plane of incidence.
struct AroundR {
    glm::vec3 r, b1, b2;
    glm::vec3 dir(float alphaDeg, float betaDeg) const {
        const float a = glm::radians(alphaDeg), b = glm::radians(betaDeg);
        return std::cos(a) * r + std::sin(a) * (std::cos(b) * b1 + std::sin(b) * b2);
    }
};

// Puts the surface's points into `s`: direction * f_r for the light s.i, s.peak kept the largest f_r.
struct LobeSampler {
    const Material& m;
    const LightingEnvironment& env;
    LobeSurface& s;

    glm::vec3 point(const glm::vec3& d) {
        const float f = fr(m, env, s.i, d);
        s.peak = std::max(s.peak, f);
        return d * f;
    }
    // One curve through directions `dirs` (dense), cut where it leaves the upper hemisphere; the cut
    // ends exactly on the horizon.
    void addCurve(const std::vector<glm::vec3>& dirs, std::vector<std::vector<glm::vec3>>& out) {
        std::vector<glm::vec3> current;
        for (std::size_t k = 0; k < dirs.size(); ++k) {
            const glm::vec3& d = dirs[k];
            if (k > 0 && (dirs[k - 1].y >= 0.0f) != (d.y >= 0.0f)) {
                const glm::vec3& p = dirs[k - 1];
                const float t = p.y / (p.y - d.y);
                glm::vec3 h = p + t * (d - p);
                h.y = 0.0f;
                if (glm::length(h) > 1e-6f) current.push_back(point(glm::normalize(h)));
                if (d.y < 0.0f) {
                    if (current.size() > 1) out.push_back(std::move(current));
                    current.clear();
                }
            }
            if (d.y >= 0.0f) current.push_back(point(d));
        }
        if (current.size() > 1) out.push_back(std::move(current));
    }
};

// Meridians through R every 15 degrees around it, densely out to three half widths from R (where
// the lobe is), then every degree.
void addMeridians(LobeSampler& sampler, const AroundR& grid, float halfWidth) {
    std::vector<float> alphas;
    for (int q = 0; q <= 120; ++q) alphas.push_back(3.0f * halfWidth * float(q) / 120.0f);
    for (int d = 1; d <= 180; ++d)
        if (float(d) > 3.0f * halfWidth) alphas.push_back(float(d));
    for (int b = 0; b < 360; b += 15) {
        std::vector<glm::vec3> dirs;
        dirs.reserve(alphas.size());
        for (float a : alphas) dirs.push_back(grid.dir(a, float(b)));
        sampler.addCurve(dirs, sampler.s.meridians);
    }
}

// Rings around R at 0.5 to 3 half widths, and every 15 degrees where that is not close to one of them.
void addRings(LobeSampler& sampler, const AroundR& grid, float halfWidth) {
    std::vector<float> ringAlphas;
    for (float f : {0.5f, 1.0f, 1.5f, 2.0f, 3.0f}) ringAlphas.push_back(f * halfWidth);
    for (int d = 15; d < 180; d += 15)
        if (std::none_of(ringAlphas.begin(), ringAlphas.end(), [&](float a) { return std::abs(a - float(d)) < 6.0f; }))
            ringAlphas.push_back(float(d));
    for (float a : ringAlphas) {
        std::vector<glm::vec3> dirs;
        for (int b = 0; b <= 360; b += 3) dirs.push_back(grid.dir(a, float(b)));
        sampler.addCurve(dirs, sampler.s.rings);
    }
}

// The plane of incidence from the light's side horizon over N to the mirror side's, densely near R.
void addPlaneOfIncidence(LobeSampler& sampler, const glm::vec3& lightSide, float incidenceDeg, float halfWidth) {
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    auto inPlane = [&](float signedThetaDeg) {  // < 0: on the light's side
        const float t = glm::radians(signedThetaDeg);
        return std::cos(t) * n - std::sin(t) * lightSide;
    };
    std::vector<float> thetas;
    for (int d = -90; d <= 90; ++d) thetas.push_back(float(d));
    for (int q = -120; q <= 120; ++q) thetas.push_back(incidenceDeg + 3.0f * halfWidth * float(q) / 120.0f);
    std::sort(thetas.begin(), thetas.end());
    for (float t : thetas)
        if (t >= -90.0f && t <= 90.0f) sampler.s.planeOfIncidence.push_back(sampler.point(inPlane(t)));
}

}  // namespace

LobeSurface sampleLobeSurface(const Material& m, const LightingEnvironment& env, const glm::vec3& toLight) {
    LobeSurface s;
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    s.i = toLight;
    s.r = 2.0f * glm::dot(n, s.i) * n - s.i;  // R(I) = 2 (N.I) N - I
    const float incidenceDeg = glm::degrees(std::acos(std::clamp(s.i.y, -1.0f, 1.0f)));
    // The light's side of the surface: its direction projected on the surface (at normal incidence, -T).
    const glm::vec3 flat(s.i.x, 0.0f, s.i.z);
    const glm::vec3 lightSide = glm::length(flat) > 1e-6f ? glm::normalize(flat) : glm::vec3(-1.0f, 0.0f, 0.0f);
    const glm::vec3 b1 = glm::cross(n, lightSide);
    const AroundR grid{s.r, b1, glm::cross(s.r, b1)};
    const float halfWidth = lobeHalfWidthDeg(m, env);
    LobeSampler sampler{m, env, s};
    addMeridians(sampler, grid, halfWidth);
    addRings(sampler, grid, halfWidth);
    addPlaneOfIncidence(sampler, lightSide, incidenceDeg, halfWidth);
    return s;
}

glm::vec2 lobe3dProjection(const glm::vec3& p, const LobeView& view) {
    const glm::vec3 eye = directionAt(90.0f - std::clamp(view.elevationDeg, 0.0f, 89.0f), view.azimuthDeg);
    const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), eye));
    const glm::vec3 up = glm::cross(eye, right);
    return {glm::dot(p, right), glm::dot(p, up)};
}

LobeIncidence lobeIncidence(float incidenceDeg) {
    LobeIncidence li;
    li.toLight = directionAt(incidenceDeg, 180.0f);
    return li;
}

std::optional<LobeIncidence> lobeIncidenceAt(const glm::vec3& n, const glm::vec3& i, const glm::vec3& v,
                                             const TangentFrame* frame) {
    if (glm::dot(n, i) <= 1e-4f) return std::nullopt;
    glm::vec3 t, b;
    if (frame) {
        t = frame->tangent;
        b = frame->bitangent;
    } else {
        // Isotropic: T opposite to I's part along the surface (I on the left), B = N x T as in the plot.
        const glm::vec3 flat = i - glm::dot(n, i) * n;
        if (glm::length(flat) > 1e-6f) {
            t = -glm::normalize(flat);
        } else {  // I along N: any T across N
            t = glm::normalize(
                glm::cross(n, std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f)));
        }
        b = glm::cross(n, t);
    }
    // The plot's frame: T = +x, N = +y, B = -z.
    auto local = [&](const glm::vec3& d) {
        return glm::normalize(glm::vec3(glm::dot(d, t), glm::dot(d, n), -glm::dot(d, b)));
    };
    LobeIncidence li;
    li.toLight = local(i);
    li.toEye = local(v);
    return li;
}

Plot lobe3dPlot(const Material& m, const LightingEnvironment& env, float incidenceDeg, const LobeView& view) {
    return lobe3dPlot(m, env, lobeIncidence(incidenceDeg), view);
}

namespace {

std::vector<glm::vec2> projected(const std::vector<glm::vec3>& points, const LobeView& view) {
    std::vector<glm::vec2> out;
    out.reserve(points.size());
    for (const glm::vec3& q : points) out.push_back(lobe3dProjection(q, view));
    return out;
}

// The title: where the light is (theta_i as the slider gives it, 0.1 deg; phi_i matters only to an
// anisotropic lobe) and which lobe; the subtitle: what the radius is.
void setLobe3dHeader(Plot& p, const Material& m, const LightingEnvironment& env, const LobeIncidence& incidence) {
    const glm::vec3& i = incidence.toLight;
    const float incidenceDeg = glm::degrees(std::acos(std::clamp(i.y, -1.0f, 1.0f)));
    std::string angles = "theta_i = " + shortNumber(std::round(incidenceDeg * 10.0f) / 10.0f) + " deg";
    if (anisotropicLobe(m, env) && std::abs(i.y) < 0.99999f) {
        const float phi = glm::degrees(std::atan2(-i.z, i.x));
        angles += ", phi_i = " + shortNumber(std::round((phi < 0.0f ? phi + 360.0f : phi) * 10.0f) / 10.0f) + " deg";
    }
    p.title = "BRDF lobe f_r(omega_i -> omega_o)" + (incidence.where.empty() ? std::string() : " " + incidence.where) +
              ": " + angles + ", " + lobeName(m, env);
    p.subtitle = "radius = f_r = k_d + k_s spec / (N.I) over the hemisphere of omega_o (k_d = " + shortNumber(m.kd) +
                 ", k_s = " + shortNumber(m.ks) + ")" + specularModifiers(env);
}

// The surface's plane: `circles` circles `step` apart (round f_r values), labelled at the front, and
// dashed spokes every 45 degrees.
void addSurfacePlane(Plot& p, float step, int circles, const LobeView& view) {
    for (int c = 1; c <= circles; ++c) {
        const float radius = step * float(c);
        std::vector<glm::vec3> circle;
        for (int d = 0; d <= 360; d += 4) circle.push_back(radius * directionAt(90.0f, float(d)));
        p.lines.push_back(line("grid", projected(circle, view), kPlotGrid));
        p.labels.push_back(label(lobe3dProjection(radius * directionAt(90.0f, view.azimuthDeg - 30.0f), view),
                                 shortNumber(radius), {0.5f, 0.0f}, {0.0f, 0.2f}, kPlotAxis));
    }
    const float outer = step * float(circles);
    for (int d = 0; d < 360; d += 45) {
        PlotPolyline spoke =
            line("grid", projected({glm::vec3(0.0f), outer * directionAt(90.0f, float(d))}, view), kPlotGrid);
        spoke.dashed = true;
        p.lines.push_back(std::move(spoke));
    }
}

// The lobe's mesh (meridians and rings, one legend entry per family) and its cut by the plane of
// incidence over it.
void addLobeMesh(Plot& p, const LobeSurface& s, const LobeView& view) {
    for (const auto& ring : s.meridians) p.lines.push_back(line("meridian", projected(ring, view), kMeridianColor));
    for (const auto& ring : s.rings) p.lines.push_back(line("ring", projected(ring, view), kRingColor));
    if (!p.lines.empty()) {
        for (auto it = p.lines.begin(); it != p.lines.end(); ++it)
            if (it->name == "meridian") {
                it->inLegend = true;
                it->name = "meridians through R";
                break;
            }
        for (auto it = p.lines.begin(); it != p.lines.end(); ++it)
            if (it->name == "ring") {
                it->inLegend = true;
                it->name = "rings around R";
                break;
            }
    }
    PlotPolyline cut = line("in the plane of incidence", projected(s.planeOfIncidence, view), kYellow, 2.0f);
    cut.inLegend = true;
    p.lines.push_back(std::move(cut));
}

// N, omega_i (toward the light) and R from the point outward, as in the lobe plot; V when the eye is
// known; T and B when the lobe is anisotropic.
void addLobe3dArrows(Plot& p, const LobeSurface& s, const std::optional<glm::vec3>& toEye, bool anisotropic,
                     float arrowLength, const LobeView& view) {
    auto arrow = [&](const std::string& name, const glm::vec3& d, Rgba8 color, bool dashed, glm::vec2 align) {
        PlotPolyline a = line(name, projected({glm::vec3(0.0f), arrowLength * d}, view), color, 1.5f);
        a.arrow = true;
        a.dashed = dashed;
        p.lines.push_back(std::move(a));
        p.labels.push_back(label(lobe3dProjection(arrowLength * d, view), name, align, {0.0f, 0.0f}, color));
    };
    arrow("N", glm::vec3(0.0f, 1.0f, 0.0f), kPlotText, false, {0.5f, 1.1f});
    arrow("omega_i", s.i, kGreen, false, {1.0f, 1.0f});
    arrow("R", s.r, kPlotAxis, true, {0.0f, 1.0f});
    if (toEye) arrow("V", *toEye, kSkyBlue, false, {0.5f, 1.1f});
    if (anisotropic) {
        const TangentFrame f = plotTangentFrame();
        arrow("T (k_t)", f.tangent, kPurple, false, {0.0f, 0.0f});
        arrow("B (k_b)", f.bitangent, kPurple, false, {1.0f, 0.0f});
    }
}

// The shown rectangle: every point of the picture, with a little room.
void fitToLines(Plot& p) {
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (const PlotPolyline& l : p.lines)
        for (const glm::vec2& q : l.points) {
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
        }
    const glm::vec2 margin = 0.04f * (hi - lo);
    p.min = lo - margin;
    p.max = hi + margin;
}

}  // namespace

Plot lobe3dPlot(const Material& m, const LightingEnvironment& env, const LobeIncidence& incidence,
                const LobeView& view) {
    const LobeSurface s = sampleLobeSurface(m, env, incidence.toLight);
    const float peak = s.peak > 1e-6f ? s.peak : 1.0f;
    const float step = niceStep(peak, 3);
    const int circles = std::max(1, int(std::ceil(peak / step - 1e-4f)));
    const float outer = step * float(circles);

    Plot p;
    p.kind = PlotKind::Lobe3d;
    setLobe3dHeader(p, m, env, incidence);
    p.equalAspect = true;
    addSurfacePlane(p, step, circles, view);
    addLobeMesh(p, s, view);
    addLobe3dArrows(p, s, incidence.toEye, anisotropicLobe(m, env), 1.15f * outer, view);
    fitToLines(p);
    return p;
}

// ---- The heat maps

BrdfSliceGrid sampleIncidencePlane(const Material& m, const LightingEnvironment& env, float phiIDeg) {
    BrdfSliceGrid g;
    g.columns = 90;
    g.rows = 180;
    g.values.reserve(std::size_t(g.columns * g.rows));
    for (int row = 0; row < g.rows; ++row) {
        const float thetaO = -89.5f + float(row);  // signed: < 0 on the light's side
        const glm::vec3 v = directionAt(std::abs(thetaO), phiIDeg + (thetaO < 0.0f ? 0.0f : 180.0f));
        for (int c = 0; c < g.columns; ++c) g.values.push_back(fr(m, env, directionAt(0.5f + float(c), phiIDeg), v));
    }
    return g;
}

BrdfSliceGrid sampleAzimuthSlice(const Material& m, const LightingEnvironment& env, float thetaIDeg, float phiIDeg) {
    BrdfSliceGrid g;
    g.columns = 180;
    g.rows = 90;
    g.values.reserve(std::size_t(g.columns * g.rows));
    const glm::vec3 i = directionAt(thetaIDeg, phiIDeg);
    for (int row = 0; row < g.rows; ++row)
        for (int c = 0; c < g.columns; ++c)
            g.values.push_back(fr(m, env, i, directionAt(0.5f + float(row), phiIDeg + 1.0f + 2.0f * float(c))));
    return g;
}

Rgba8 heatColor(float t) {
    // Viridis at nine stops (matplotlib's), linearly between them.
    static const std::uint8_t kStops[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},
                                              {44, 113, 142}, {33, 145, 140}, {39, 173, 129},
                                              {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
    const float x = std::clamp(t, 0.0f, 1.0f) * 8.0f;
    const int k = std::min(7, int(x));
    const float f = x - float(k);
    auto mix = [&](int ch) {
        return std::uint8_t(std::lround(float(kStops[k][ch]) + (float(kStops[k + 1][ch]) - float(kStops[k][ch])) * f));
    };
    return Rgba8{mix(0), mix(1), mix(2), 255};
}

namespace {

// A heat map's colour scale: log10 f_r from lo to hi. f_r = k_d + k_s spec / (N.I) grows without bound
// as theta_i nears 90 deg (the 1 / (N.I); the heuristic lobe is not reciprocal), so in the plane of
// incidence hi is the largest value up to theta_i = kClipThetaIDeg and larger ones take the top colour
// (the bar says ">="). lo is the smallest value, at most three decades below hi (k_d = 0 has 0s).
struct HeatScale {
    float lo = 0.1f, hi = 1.0f;
    bool clipped = false;
    float t(float v) const { return hi > lo ? std::log10(std::max(v, 1e-30f) / lo) / std::log10(hi / lo) : 1.0f; }
};
constexpr float kClipThetaIDeg = 80.0f;

HeatScale heatScale(const std::vector<const BrdfSliceGrid*>& grids, bool clipGrazing) {
    HeatScale s;
    float lo = 1e30f, hi = 0.0f, all = 0.0f;
    for (const BrdfSliceGrid* g : grids)
        for (int row = 0; row < g->rows; ++row)
            for (int c = 0; c < g->columns; ++c) {
                const float v = g->at(c, row);
                all = std::max(all, v);
                lo = std::min(lo, v);
                if (!clipGrazing || 0.5f + float(c) <= kClipThetaIDeg) hi = std::max(hi, v);
            }
    s.hi = hi > 0.0f ? hi : 1.0f;
    s.lo = std::max(lo, s.hi * 1e-3f);
    if (s.lo >= s.hi) s.lo = 0.5f * s.hi;  // a constant BRDF (k_s = 0): one colour, the bar still reads
    s.clipped = all > s.hi * 1.0001f;
    return s;
}

// Where the panels go, in plot units, each 1 tall: the plane of incidence (a) 1 wide with its colour
// bar, the azimuth slice (b) 1.5 wide with its own; rows 1.6 apart (room for the axis numbers and names).
constexpr float kAX0 = 0.0f, kAX1 = 1.0f, kABar0 = 1.1f, kABar1 = 1.16f;
constexpr float kBX0 = 1.8f, kBX1 = 3.3f, kBBar0 = 3.36f, kBBar1 = 3.42f;
constexpr float kRowStep = 1.6f;

// One heat map over [x0, x1] x [y0, y0 + 1], framed, "theta_o" over its top left corner.
void addHeatPanel(Plot& p, const BrdfSliceGrid& g, const HeatScale& scale, float x0, float x1, float y0) {
    const float y1 = y0 + 1.0f;
    PlotHeatMap h;
    h.min = {x0, y0};
    h.max = {x1, y1};
    h.columns = g.columns;
    h.rows = g.rows;
    for (float v : g.values) h.cells.push_back(heatColor(scale.t(v)));
    p.heatMaps.push_back(std::move(h));
    p.lines.push_back(line("frame", {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}}, kPlotAxis));
    p.labels.push_back(label({x0, y1}, "theta_o", {0.0f, 1.0f}, {0.0f, -0.3f}));
}

// The plane of incidence's axes in the row at y0: theta_i along x (0..90), signed theta_o along y:
// 90 .. 0 .. 90 with the mirror side up; R's diagonal theta_o = theta_i.
void addIncidencePlaneAxes(Plot& p, float y0) {
    auto ax = [&](float thetaI) { return kAX0 + (kAX1 - kAX0) * thetaI / 90.0f; };
    auto ay = [&](float thetaO) { return y0 + (thetaO + 90.0f) / 180.0f; };
    for (int d = 0; d <= 90; d += 30)
        p.labels.push_back(label({ax(float(d)), y0}, std::to_string(d), {0.5f, 0.0f}, {0.0f, 0.2f}, kPlotAxis));
    for (int d = -90; d <= 90; d += 45)
        p.labels.push_back(
            label({kAX0, ay(float(d))}, std::to_string(std::abs(d)), {1.0f, 0.5f}, {-0.3f, 0.0f}, kPlotAxis));
    p.labels.push_back(label({0.5f * (kAX0 + kAX1), y0}, "theta_i (deg)", {0.5f, 0.0f}, {0.0f, 1.3f}));
    p.labels.push_back(label({kAX0, ay(90.0f)}, "delta_phi = 180", {0.0f, 0.0f}, {0.3f, 0.2f}));
    p.labels.push_back(label({kAX0, ay(-90.0f)}, "delta_phi = 0", {0.0f, 1.0f}, {0.3f, -0.2f}));
    PlotPolyline mirror = line("R", {{ax(0.0f), ay(0.0f)}, {ax(90.0f), ay(90.0f)}}, kPlotText, 1.0f);
    mirror.dashed = true;
    p.lines.push_back(std::move(mirror));
    p.labels.push_back(label({ax(45.0f), ay(45.0f)}, "R", {0.0f, 0.0f}, {0.4f, 0.0f}, kPlotText));
}

// The azimuth slice's axes in the row at y0: delta_phi along x (0..360), theta_o along y (0..90); R
// marked at (180, theta_i) by two ticks that leave it visible.
void addAzimuthSliceAxes(Plot& p, float y0, float incidenceDeg) {
    auto bx = [&](float dphi) { return kBX0 + (kBX1 - kBX0) * dphi / 360.0f; };
    auto by = [&](float thetaO) { return y0 + thetaO / 90.0f; };
    for (int d = 0; d <= 360; d += 90)
        p.labels.push_back(label({bx(float(d)), y0}, std::to_string(d), {0.5f, 0.0f}, {0.0f, 0.2f}, kPlotAxis));
    for (int d = 0; d <= 90; d += 30)
        p.labels.push_back(label({kBX0, by(float(d))}, std::to_string(d), {1.0f, 0.5f}, {-0.3f, 0.0f}, kPlotAxis));
    p.labels.push_back(label({0.5f * (kBX0 + kBX1), y0}, "delta_phi (deg)", {0.5f, 0.0f}, {0.0f, 1.3f}));
    PlotPolyline rMark =
        line("R", {{bx(180.0f), by(incidenceDeg) - 0.08f}, {bx(180.0f), by(incidenceDeg) - 0.03f}}, kPlotText, 1.5f);
    p.lines.push_back(rMark);
    rMark.points = {{bx(180.0f), by(incidenceDeg) + 0.03f}, {bx(180.0f), by(incidenceDeg) + 0.08f}};
    p.lines.push_back(std::move(rMark));
    p.labels.push_back(label({bx(180.0f), by(incidenceDeg)}, "R", {0.0f, 0.5f}, {0.6f, 0.0f}, kPlotText));
}

// A colour bar over [x0, x1] x [0, top]: lo at the bottom, hi at the top, ticks evenly in log f_r.
void addColourBar(Plot& p, float x0, float x1, const HeatScale& scale, float top) {
    PlotHeatMap bar;
    bar.min = {x0, 0.0f};
    bar.max = {x1, top};
    bar.columns = 1;
    bar.rows = 240;
    for (int r = 0; r < bar.rows; ++r) bar.cells.push_back(heatColor((float(r) + 0.5f) / float(bar.rows)));
    p.heatMaps.push_back(std::move(bar));
    p.lines.push_back(line("frame", {{x0, 0.0f}, {x1, 0.0f}, {x1, top}, {x0, top}, {x0, 0.0f}}, kPlotAxis));
    const int ticks = 3;
    for (int k = 0; k <= ticks; ++k) {
        const float y = top * float(k) / float(ticks);
        const float value = scale.lo * std::pow(scale.hi / scale.lo, float(k) / float(ticks));
        p.lines.push_back(line("tick", {{x1, y}, {x1 + 0.03f, y}}, kPlotAxis));
        const std::string text = (k == ticks && scale.clipped ? ">=" : "") + format("%.3g", double(value));
        p.labels.push_back(label({x1, y}, text, {0.0f, 0.5f}, {0.4f, 0.0f}, kPlotAxis));
    }
    p.labels.push_back(label({x0, top}, "f_r", {0.0f, 1.0f}, {0.0f, -0.3f}));
}

}  // namespace

Plot brdfSlicePlot(const Material& m, const LightingEnvironment& env, float incidenceDeg) {
    const bool anisotropic = anisotropicLobe(m, env);
    const std::vector<float> phis =
        anisotropic ? std::vector<float>{90.0f, 0.0f} : std::vector<float>{0.0f};  // bottom row first
    std::vector<BrdfSliceGrid> planes, slices;
    for (float phi : phis) {
        planes.push_back(sampleIncidencePlane(m, env, phi));
        slices.push_back(sampleAzimuthSlice(m, env, incidenceDeg, phi));
    }
    std::vector<const BrdfSliceGrid*> planePtrs, slicePtrs;
    for (std::size_t r = 0; r < phis.size(); ++r) {
        planePtrs.push_back(&planes[r]);
        slicePtrs.push_back(&slices[r]);
    }
    // One scale per kind of panel, shared by the rows so that phi_i = 0 and 90 compare.
    const HeatScale planeScale = heatScale(planePtrs, true), sliceScale = heatScale(slicePtrs, false);

    Plot p;
    p.kind = PlotKind::BrdfSlice;
    p.title = "BRDF f_r(delta_phi; theta_i -> theta_o): " + lobeName(m, env);
    p.subtitle = "colour: log f_r, f_r = k_d + k_s spec / (N.I), k_d = " + shortNumber(m.kd) +
                 ", k_s = " + shortNumber(m.ks) + specularModifiers(env) + "; delta_phi = phi_o - phi_i";
    if (anisotropic)
        p.subtitle +=
            "; rows: light along T (phi_i = 0) and along B (phi_i = 90 deg) differ: f_r needs phi_i too (4-D)";
    for (std::size_t r = 0; r < phis.size(); ++r) {
        const float y0 = kRowStep * float(r);
        addHeatPanel(p, planes[r], planeScale, kAX0, kAX1, y0);
        addHeatPanel(p, slices[r], sliceScale, kBX0, kBX1, y0);
        if (anisotropic)  // which row, in the azimuth slice's top right corner (dark: the lobe is at 180)
            p.labels.push_back(label({kBX1, y0 + 1.0f}, r == 1 ? "phi_i = 0, along T" : "phi_i = 90 deg, along B",
                                     {1.0f, 0.0f}, {-0.3f, 0.2f}, kYellow));
        addIncidencePlaneAxes(p, y0);
        addAzimuthSliceAxes(p, y0, incidenceDeg);
    }
    // The colour bars, as tall as the rows.
    const float barTop = kRowStep * float(phis.size() - 1) + 1.0f;
    addColourBar(p, kABar0, kABar1, planeScale, barTop);
    addColourBar(p, kBBar0, kBBar1, sliceScale, barTop);
    p.min = {kAX0, 0.0f};
    p.max = {kBBar1, barTop};
    return p;
}

}  // namespace shadelab
