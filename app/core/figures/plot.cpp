#include "core/figures/plot.hpp"
#include "core/figures/plot_parts.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace shadelab {
namespace {

using namespace plot_parts;

constexpr float kCurveWidth = 2.0f;

// Sorted, with values closer than `tolerance` merged.
std::vector<float> sortedUnique(std::vector<float> values, float tolerance) {
    std::sort(values.begin(), values.end());
    std::vector<float> out;
    for (float v : values)
        if (out.empty() || v - out.back() > tolerance) out.push_back(v);
    return out;
}

glm::vec2 unitAt(float angleFromNDeg) {
    const float a = glm::radians(angleFromNDeg);
    return {std::sin(a), std::cos(a)};
}

}  // namespace

const char* toString(PlotKind kind) { return nameOf(kPlotKindNames, kind); }

std::vector<LobeSample> sampleLobe(const LightingEnvironment& env, float ke, float incidenceDeg) {
    std::vector<float> angles;
    for (int d = -90; d <= 90; ++d) angles.push_back(float(d));
    // Phong's lobe falls to 1% at acos(0.01^(1/k_e)) from R; Blinn-Phong's spans about twice that in V
    // (N.H = cos of half V's angle from R, in this plane). 400 more samples over 1.5 times that width
    // keep a k_e = 10000 lobe (1.35 degrees wide at half height) smooth.
    const float halfWidthDeg = 2.0f * glm::degrees(std::acos(std::pow(0.01f, 1.0f / ke))) * 1.5f;
    const int extra = 200;
    for (int k = -extra; k <= extra; ++k) {
        const float a = incidenceDeg + halfWidthDeg * float(k) / float(extra);
        if (a >= -90.0f && a <= 90.0f) angles.push_back(a);
    }
    angles = sortedUnique(std::move(angles), 1e-4f);

    LightingEnvironment phongEnv = env, blinnEnv = env;
    phongEnv.model = ReflectionModel::Phong;
    blinnEnv.model = ReflectionModel::BlinnPhong;
    const glm::vec2 i2 = unitAt(-incidenceDeg);
    const glm::vec3 n(0.0f, 1.0f, 0.0f), i(i2.x, i2.y, 0.0f);
    std::vector<LobeSample> samples;
    samples.reserve(angles.size());
    for (float a : angles) {
        const glm::vec2 v2 = unitAt(a);
        const glm::vec3 v(v2.x, v2.y, 0.0f);
        samples.push_back({a, specularTerm(phongEnv, ke, n, i, v), specularTerm(blinnEnv, ke, n, i, v)});
    }
    return samples;
}

std::optional<float> criticalAngleDeg(float eta1, float eta2) {
    if (eta1 <= eta2) return std::nullopt;
    return glm::degrees(std::asin(eta2 / eta1));
}

float brewsterAngleDeg(float eta1, float eta2) { return glm::degrees(std::atan(eta2 / eta1)); }

std::vector<FresnelSample> sampleFresnel(float eta1, float eta2) {
    std::vector<float> angles;
    for (int q = 0; q <= 360; ++q) angles.push_back(float(q) * 0.25f);
    angles.push_back(brewsterAngleDeg(eta1, eta2));
    if (const auto critical = criticalAngleDeg(eta1, eta2)) {
        // The exact curves rise with infinite slope into the critical angle: sample that last stretch
        // densely, and the angle itself (where fresnelExact reports total reflection).
        for (int k = 1; k <= 40; ++k) angles.push_back(*critical - 2.0f * float(k * k) / 1600.0f);
        angles.push_back(*critical);
    }
    angles = sortedUnique(std::move(angles), 1e-5f);
    std::vector<FresnelSample> samples;
    samples.reserve(angles.size());
    for (float a : angles) {
        const float c = std::cos(glm::radians(a));
        samples.push_back({a, fresnelExact(c, eta1, eta2), fresnelSchlick(c, eta1, eta2)});
    }
    return samples;
}

namespace {

// The reference half circles, `rings` of them `step` apart (labelled along the surface), the dashed
// spokes every 30 degrees from N (labelled with their angle) and the surface.
void addLobeGrid(Plot& p, float step, int rings, float incidenceDeg) {
    const float r = step * float(rings);
    for (int k = 1; k <= rings; ++k) {
        const float radius = step * float(k);
        std::vector<glm::vec2> arc;
        for (int d = -90; d <= 90; d += 2) arc.push_back(radius * unitAt(float(d)));
        p.lines.push_back(line("grid", std::move(arc), kPlotGrid));
        p.labels.push_back(label({radius, 0.0f}, shortNumber(radius), {0.5f, 0.0f}, {0.0f, 0.25f}, kPlotAxis));
    }
    for (int d : {-60, -30, 30, 60}) {
        PlotPolyline spoke = line("grid", {{0.0f, 0.0f}, r * unitAt(float(d))}, kPlotGrid);
        spoke.dashed = true;
        p.lines.push_back(std::move(spoke));
        // Where I or R runs along a spoke, the arrow's letter stands there and the angle is the title's.
        if (std::abs(std::abs(float(d)) - incidenceDeg) < 8.0f) continue;
        p.labels.push_back(label(r * unitAt(float(d)), std::to_string(std::abs(d)), {d < 0 ? 1.0f : 0.0f, 1.0f},
                                 {d < 0 ? -0.2f : 0.2f, 0.0f}, kPlotAxis));
    }
    p.lines.push_back(line("surface", {{-1.12f * r, 0.0f}, {1.12f * r, 0.0f}}, kPlotAxis, 1.5f));
    p.labels.push_back(label({-1.12f * r, 0.0f}, "surface", {0.0f, 0.0f}, {0.0f, 0.25f}, kPlotAxis));
}

// N, I (toward the light) and R = 2(N.I)N - I, drawn as the lecture draws them: from the point outward.
// Labels above the tips, I's to the left and R's to the right, so that at normal incidence (all three
// along N) they stand side by side as "I N R".
void addLobeArrows(Plot& p, float arrowLength, float incidenceDeg) {
    auto arrow = [&](const std::string& name, float angleDeg, Rgba8 color, bool dashed, float side) {
        PlotPolyline a = line(name, {{0.0f, 0.0f}, arrowLength * unitAt(angleDeg)}, color, 1.5f);
        a.arrow = true;
        a.dashed = dashed;
        p.lines.push_back(std::move(a));
        p.labels.push_back(
            label(arrowLength * unitAt(angleDeg), name, {0.5f - 0.5f * side, 1.0f}, {0.6f * side, -0.15f}, color));
    };
    arrow("N", 0.0f, kPlotText, false, 0.0f);
    arrow("I", -incidenceDeg, kYellow, false, -1.0f);
    arrow("R", incidenceDeg, kPlotAxis, true, 1.0f);
}

// Phong's and Blinn-Phong's lobes as polar curves, the model in use marked in the legend.
void addLobeCurves(Plot& p, const std::vector<LobeSample>& samples, ReflectionModel inUse) {
    auto curve = [&](ReflectionModel model, const char* name, Rgba8 color) {
        PlotPolyline c = line(name, {}, color, kCurveWidth);
        if (model == inUse) c.name += "  (in use)";
        c.inLegend = true;
        for (const LobeSample& s : samples)
            c.points.push_back((model == ReflectionModel::Phong ? s.phong : s.blinnPhong) * unitAt(s.angleDeg));
        p.lines.push_back(std::move(c));
    };
    curve(ReflectionModel::Phong, "Phong max(0, R.V)^k_e", kOrange);
    curve(ReflectionModel::BlinnPhong, "Blinn-Phong max(0, N.H)^k_e", kSkyBlue);
}

}  // namespace

Plot lobePlot(const LightingEnvironment& env, float ke, float incidenceDeg) {
    const std::vector<LobeSample> samples = sampleLobe(env, ke, incidenceDeg);
    float peak = 0.0f;
    for (const LobeSample& s : samples) peak = std::max({peak, s.phong, s.blinnPhong});
    // Reference half circles at up to four round spec values; the outer one reaches the higher peak.
    // A peak of float rounding only (Fresnel at ior 1 reflects nothing) keeps the scale of 1.
    if (peak < 1e-6f) peak = 1.0f;
    const float step = niceStep(peak, 4);
    const int rings = std::max(1, int(std::ceil(peak / step - 1e-4f)));
    const float r = step * float(rings);

    Plot p;
    p.kind = PlotKind::Lobe;
    p.title = "Specular lobe: k_e = " + shortNumber(ke) + ", theta_i = " + shortNumber(incidenceDeg) + " deg";
    p.subtitle = "radius = spec for V in the plane of incidence" + specularModifiers(env);
    p.min = {-1.22f * r, -0.1f * r};
    p.max = {1.22f * r, 1.18f * r};
    p.equalAspect = true;
    addLobeGrid(p, step, rings, incidenceDeg);
    addLobeArrows(p, 1.1f * r, incidenceDeg);
    addLobeCurves(p, samples, env.model);
    return p;
}

Plot fresnelPlot(float eta1, float eta2) {
    const std::vector<FresnelSample> samples = sampleFresnel(eta1, eta2);
    const std::optional<float> critical = criticalAngleDeg(eta1, eta2);
    Plot p;
    p.kind = PlotKind::Fresnel;
    p.title =
        "Fresnel reflectance: eta_1 = " + format("%.2f", double(eta1)) + " -> eta_2 = " + format("%.2f", double(eta2));
    p.subtitle = "R_0 = " + format("%.3f", double(fresnelR0(eta1, eta2)));
    if (critical) p.subtitle += ", total internal reflection beyond " + format("%.1f", double(*critical)) + " deg";
    p.min = {0.0f, 0.0f};
    p.max = {90.0f, 1.0f};

    for (int d = 15; d < 90; d += 15) p.lines.push_back(line("grid", {{float(d), 0.0f}, {float(d), 1.0f}}, kPlotGrid));
    for (int k = 1; k < 5; ++k)
        p.lines.push_back(line("grid", {{0.0f, 0.2f * float(k)}, {90.0f, 0.2f * float(k)}}, kPlotGrid));
    p.lines.push_back(
        line("frame", {{0.0f, 0.0f}, {90.0f, 0.0f}, {90.0f, 1.0f}, {0.0f, 1.0f}, {0.0f, 0.0f}}, kPlotAxis));
    for (int d = 0; d <= 90; d += 15)
        p.labels.push_back(label({float(d), 0.0f}, std::to_string(d), {0.5f, 0.0f}, {0.0f, 0.3f}, kPlotAxis));
    for (int k = 0; k <= 5; ++k)
        p.labels.push_back(
            label({0.0f, 0.2f * float(k)}, format("%.1f", 0.2 * k), {1.0f, 0.5f}, {-0.4f, 0.0f}, kPlotAxis));
    p.labels.push_back(label({45.0f, 0.0f}, "angle of incidence theta_1 (deg)", {0.5f, 0.0f}, {0.0f, 1.5f}));
    p.labels.push_back(label({0.0f, 1.0f}, "R", {0.5f, 1.0f}, {0.0f, -0.4f}));

    auto curve = [&](const char* name, Rgba8 color, float width, bool dashed, auto value) {
        PlotPolyline c = line(name, {}, color, width);
        c.dashed = dashed;
        c.inLegend = true;
        for (const FresnelSample& s : samples) c.points.push_back({s.angleDeg, value(s)});
        p.lines.push_back(std::move(c));
    };
    curve("R_par", kSkyBlue, kCurveWidth, false, [](const FresnelSample& s) { return s.exact.parallel; });
    curve("R_perp", kVermillion, kCurveWidth, false, [](const FresnelSample& s) { return s.exact.perpendicular; });
    curve("(R_par + R_perp) / 2", kPlotText, kCurveWidth, false,
          [](const FresnelSample& s) { return s.exact.average; });
    curve("Schlick", kGreen, kCurveWidth, true, [](const FresnelSample& s) { return s.schlick; });
    // The marked angles last: in the legend after the curves, and drawn over them.
    const float brewster = brewsterAngleDeg(eta1, eta2);
    PlotPolyline brewsterLine = line("Brewster " + format("%.1f", double(brewster)) + " deg (R_par = 0)",
                                     {{brewster, 0.0f}, {brewster, 1.0f}}, kPurple);
    brewsterLine.dashed = brewsterLine.inLegend = true;
    p.lines.push_back(std::move(brewsterLine));
    if (critical) {
        PlotPolyline c = line("critical angle " + format("%.1f", double(*critical)) + " deg",
                              {{*critical, 0.0f}, {*critical, 1.0f}}, kYellow, 1.5f);
        c.dashed = c.inLegend = true;
        p.lines.push_back(std::move(c));
    }
    return p;
}

Plot scenePlot(PlotKind kind, const Scene& scene, const Material& material, const PlotSettings& settings) {
    switch (kind) {
    case PlotKind::Lobe: return lobePlot(lightingEnvironment(scene), material.ke, settings.incidenceDeg);
    case PlotKind::Lobe3d:
        return lobe3dPlot(material, lightingEnvironment(scene),
                          settings.probed ? *settings.probed : lobeIncidence(settings.incidenceDeg), settings.lobeView);
    case PlotKind::BrdfSlice: return brdfSlicePlot(material, lightingEnvironment(scene), settings.incidenceDeg);
    case PlotKind::Fresnel: break;
    }
    return settings.fromInside ? fresnelPlot(scene.ior, 1.0f) : fresnelPlot(1.0f, scene.ior);
}

// ---- Layout

glm::vec2 PlotLayout::labelAt(const PlotLabel& l, glm::vec2 textSize) const {
    return toPixels(l.at) - l.align * textSize + l.offset * lineHeight;
}

namespace {

// Where the word from `start` ends: at the next space, except one before the unit "deg", so that a
// value keeps its unit on its line ("56.9 deg", which the painters' lectureNotation writes 56.9°;
// a line starting "deg," would stay ASCII).
std::size_t wordEnd(const std::string& text, std::size_t start) {
    const auto unitAt = [&](std::size_t at) {
        return text.compare(at, 3, "deg") == 0 &&
               (at + 3 >= text.size() || !std::isalpha(static_cast<unsigned char>(text[at + 3])));
    };
    std::size_t end = text.find(' ', start);
    while (end != std::string::npos && unitAt(end + 1)) end = text.find(' ', end + 1);
    return end == std::string::npos ? text.size() : end;
}

// The title and subtitle from `y` down, each wrapped at spaces to `width` (a single word wider than
// the plot stays whole); returns the y below them.
float layoutHeader(const Plot& plot, float width, float pad, const MeasureText& measure, PlotLayout& out, float y) {
    const float lineHeight = out.lineHeight;
    for (const auto& [text, color] : {std::pair{plot.title, kPlotText}, std::pair{plot.subtitle, kPlotAxis}}) {
        std::string row;
        std::size_t start = 0;
        while (start < text.size()) {
            const std::size_t end = wordEnd(text, start);
            const std::string word = text.substr(start, end - start);
            const std::string longer = row.empty() ? word : row + " " + word;
            if (!row.empty() && measure(longer).x > width - 2.0f * pad) {
                out.header.push_back({row, {pad, y}, color});
                y += lineHeight * 1.2f;
                row = word;
            } else {
                row = longer;
            }
            start = end + 1;
        }
        if (!row.empty()) {
            out.header.push_back({row, {pad, y}, color});
            y += lineHeight * 1.2f;
        }
    }
    return y;
}

// The legend from `y` down, flowing left to right and wrapping at `width`; returns the y below it.
float layoutLegend(const Plot& plot, float width, float pad, const MeasureText& measure, PlotLayout& out, float y) {
    const float lineHeight = out.lineHeight;
    float x = pad;
    bool rowUsed = false;
    for (std::size_t i = 0; i < plot.lines.size(); ++i) {
        if (!plot.lines[i].inLegend) continue;
        const float swatch = 2.2f * lineHeight, textWidth = measure(plot.lines[i].name).x;
        const float entryWidth = swatch + 0.4f * lineHeight + textWidth;
        if (rowUsed && x + entryWidth > width - pad) {
            x = pad;
            y += lineHeight * 1.2f;
        }
        PlotLegendEntry e;
        e.line = i;
        e.swatchFrom = {x, y + 0.5f * lineHeight};
        e.swatchTo = {x + swatch, y + 0.5f * lineHeight};
        e.textAt = {x + swatch + 0.4f * lineHeight, y};
        out.legend.push_back(e);
        x += entryWidth + 1.2f * lineHeight;
        rowUsed = true;
    }
    if (rowUsed) y += lineHeight * 1.2f;
    return y;
}

// The plot area below `top`: it starts as the rest of the rectangle and shrinks until every label fits
// inside it with `pad` to spare (axis labels sit outside the plotted range).
void fitPlotArea(const Plot& plot, glm::vec2 size, float pad, float top, const MeasureText& measure, PlotLayout& out) {
    glm::vec2 lo(pad, top), hi(size.x - pad, size.y - pad);
    for (int pass = 0; pass < 4; ++pass) {
        const glm::vec2 extent = glm::max(hi - lo, glm::vec2(1.0f));
        const glm::vec2 range = plot.max - plot.min;
        glm::vec2 scale = extent / range;
        glm::vec2 used = extent;
        if (plot.equalAspect) {
            scale = glm::vec2(std::min(scale.x, scale.y));
            used = scale * range;
        }
        out.areaMin = lo + 0.5f * (extent - used);
        out.areaMax = out.areaMin + used;
        out.pixelsPerUnit = scale;
        out.plotOrigin = {out.areaMin.x - plot.min.x * scale.x, out.areaMax.y + plot.min.y * scale.y};
        glm::vec2 overflowLo(0.0f), overflowHi(0.0f);
        for (const PlotLabel& l : plot.labels) {
            const glm::vec2 textSize = measure(l.text);
            const glm::vec2 at = out.labelAt(l, textSize);
            overflowLo = glm::max(overflowLo, glm::vec2(pad, top) - at);
            overflowHi = glm::max(overflowHi, at + textSize - (size - glm::vec2(pad)));
        }
        if (overflowLo == glm::vec2(0.0f) && overflowHi == glm::vec2(0.0f)) break;
        lo += overflowLo;
        hi -= overflowHi;
    }
}

}  // namespace

// From the top: the header, the legend, then the plot area in what is left.
PlotLayout layoutPlot(const Plot& plot, glm::vec2 size, float lineHeight, const MeasureText& measure) {
    PlotLayout out;
    out.lineHeight = lineHeight;
    const float pad = 0.6f * lineHeight;
    float y = layoutHeader(plot, size.x, pad, measure, out, pad);
    y = layoutLegend(plot, size.x, pad, measure, out, y + 0.3f * lineHeight);
    y += 0.4f * lineHeight;
    fitPlotArea(plot, size, pad, y, measure, out);
    return out;
}

PlotLayout paintPlot(const Plot& plot, glm::vec2 size, float lineUnit, PlotPainter& painter) {
    const MeasureText measure = [&](const std::string& text) { return painter.measure(text); };
    PlotLayout layout = layoutPlot(plot, size, painter.lineHeight(), measure);  // returned: moved, not copied
    auto stroke = [&](const PlotPolyline& l, const std::vector<glm::vec2>& pixels, bool arrow) {
        const float width = l.width * lineUnit;
        if (l.dashed) {
            for (const std::vector<glm::vec2>& dash : dashPolyline(pixels, 6.0f * lineUnit, 4.0f * lineUnit))
                painter.stroke(dash, l.color, width);
        } else {
            painter.stroke(pixels, l.color, width);
        }
        if (arrow && pixels.size() >= 2) {
            const auto [left, right] = arrowHead(pixels[pixels.size() - 2], pixels.back(), 8.0f * lineUnit);
            painter.fillTriangle(pixels.back(), left, right, l.color);
        }
    };
    for (const PlotHeatMap& h : plot.heatMaps) {
        // Cell edges computed once per column and row, so neighbours share them exactly.
        const glm::vec2 lo = layout.toPixels(h.min), hi = layout.toPixels(h.max);
        for (int r = 0; r < h.rows; ++r) {
            const float y0 = lo.y + (hi.y - lo.y) * float(r) / float(h.rows),
                        y1 = lo.y + (hi.y - lo.y) * float(r + 1) / float(h.rows);
            for (int c = 0; c < h.columns; ++c) {
                const float x0 = lo.x + (hi.x - lo.x) * float(c) / float(h.columns);
                const float x1 = lo.x + (hi.x - lo.x) * float(c + 1) / float(h.columns);
                painter.fillRect({x0, std::min(y0, y1)}, {x1, std::max(y0, y1)},
                                 h.cells[std::size_t(r) * std::size_t(h.columns) + std::size_t(c)]);
            }
        }
    }
    for (const PlotPolyline& l : plot.lines) {
        std::vector<glm::vec2> pixels;
        pixels.reserve(l.points.size());
        for (const glm::vec2& p : l.points)
            if (std::isfinite(p.x) && std::isfinite(p.y)) pixels.push_back(layout.toPixels(p));  // never a NaN pixel
        stroke(l, pixels, l.arrow);
    }
    for (const PlotLabel& l : plot.labels) painter.text(layout.labelAt(l, measure(l.text)), l.text, l.color);
    for (const PlotLayout::Line& line : layout.header) painter.text(line.at, line.text, line.color);
    for (const PlotLegendEntry& e : layout.legend) {
        stroke(plot.lines[e.line], {e.swatchFrom, e.swatchTo}, false);
        painter.text(e.textAt, plot.lines[e.line].name, kPlotText);
    }
    return layout;
}

std::vector<std::vector<glm::vec2>> dashPolyline(const std::vector<glm::vec2>& pixels, float dash, float gap) {
    std::vector<std::vector<glm::vec2>> dashes;
    bool drawing = true;
    float left = dash;  // length left in the current dash or gap
    std::vector<glm::vec2> current;
    if (!pixels.empty()) current.push_back(pixels.front());
    for (std::size_t k = 1; k < pixels.size(); ++k) {
        glm::vec2 a = pixels[k - 1];
        const glm::vec2 b = pixels[k];
        float length = glm::length(b - a);
        while (length > 0.0f) {
            const float t = std::min(left, length);
            const glm::vec2 m = a + (b - a) * (t / length);
            if (drawing) current.push_back(m);
            left -= t;
            length -= t;
            a = m;
            if (left <= 0.0f) {
                if (drawing && current.size() > 1) dashes.push_back(current);
                current.clear();
                drawing = !drawing;
                left = drawing ? dash : gap;
                if (drawing) current.push_back(a);
            }
        }
    }
    if (drawing && current.size() > 1) dashes.push_back(current);
    return dashes;
}

std::pair<glm::vec2, glm::vec2> arrowHead(glm::vec2 from, glm::vec2 tip, float length) {
    const glm::vec2 d = tip - from;
    const float l = glm::length(d);
    const glm::vec2 back = l > 0.0f ? d / l : glm::vec2(0.0f, -1.0f);
    const glm::vec2 side(-back.y, back.x);
    const glm::vec2 base = tip - back * length;
    return {base + side * (0.45f * length), base - side * (0.45f * length)};
}

std::string lectureNotation(std::string text) {
    static const std::pair<const char*, const char*> kSymbols[] = {{"delta_phi", "\u0394\u03c6"},
                                                                   {">=", "\u2265"},
                                                                   {"phi_", "\u03c6_"},
                                                                   {"omega_", "\u03c9_"},
                                                                   {"theta_", "\u03b8_"},
                                                                   {"eta_1", "\u03b7\u2081"},
                                                                   {"eta_2", "\u03b7\u2082"},
                                                                   {"eta_", "\u03b7_"},
                                                                   {" deg", "\u00b0"},
                                                                   {"->", "\u2192"},
                                                                   {"R_par", "R\u2225"},
                                                                   {"R_perp", "R\u22a5"},
                                                                   {"R.V", "R\u00b7V"},
                                                                   {"N.H", "N\u00b7H"},
                                                                   {"V.H", "V\u00b7H"},
                                                                   {"N.I", "N\u00b7I"}};
    // A name ending in a letter is replaced only where its word ends there (" deg" but not " degrees").
    const auto wordEnds = [&](std::size_t end, const char* ascii) {
        const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
        return !letter(ascii[std::strlen(ascii) - 1]) || end >= text.size() || !letter(text[end]);
    };
    for (const auto& [ascii, symbol] : kSymbols)
        for (std::size_t at = text.find(ascii); at != std::string::npos; at = text.find(ascii, at + 1))
            if (wordEnds(at + std::strlen(ascii), ascii)) text.replace(at, std::strlen(ascii), symbol);
    return text;
}

}  // namespace shadelab
