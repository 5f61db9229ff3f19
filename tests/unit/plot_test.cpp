// The lecture's plots (core/figures/plot.hpp, core/figures/plot_image.hpp): the curves' values against the formulas
// written out here in double precision — in the plane of incidence Phong's R.V is cos(phi - theta_i)
// and Blinn-Phong's N.H is cos((phi - theta_i) / 2) — the Fresnel curves against the lecture's tan/sin
// forms, Brewster's and the critical angle, the layout, and the rasterised PNGs against goldens.
#include "core/image/image.hpp"
#include "core/figures/plot.hpp"
#include "core/figures/plot_image.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

using namespace shadelab;

namespace {

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

const PlotPolyline& lineNamed(const Plot& plot, const std::string& prefix) {
    for (const PlotPolyline& l : plot.lines)
        if (l.name.rfind(prefix, 0) == 0) return l;
    throw std::runtime_error("no line named " + prefix);
}
bool hasLineNamed(const Plot& plot, const std::string& prefix) {
    return std::any_of(plot.lines.begin(), plot.lines.end(), [&](const PlotPolyline& l) { return l.name.rfind(prefix, 0) == 0; });
}

// Float formulas against double ones: relative error grows with the exponent (pow amplifies cos's
// ~1e-7 error k_e times), so 1e-3 relative covers k_e = 1000 with margin.
void expectClose(double actual, double expected, const std::string& what) {
    EXPECT_NEAR(actual, expected, 1e-3 * expected + 1e-6) << what;
}

}  // namespace

// ---- The BRDF as a function (issue 30, part 3): lobe3d and brdf-slice

namespace {

Material anisotropicMaterial(float kt, float kb) {
    Material m;
    m.anisotropic = true;
    m.anisotropy = {kt, kb};
    return m;
}

LightingEnvironment modelEnv(ReflectionModel model) {
    LightingEnvironment env;
    env.model = model;
    return env;
}

// All points of the plot's polylines, in order: two plots are the same picture when these are.
std::vector<glm::vec2> allPoints(const Plot& plot) {
    std::vector<glm::vec2> out;
    for (const PlotPolyline& l : plot.lines) out.insert(out.end(), l.points.begin(), l.points.end());
    return out;
}

// The point of the surface farthest from the origin (the lobe's peak) as a unit direction.
glm::vec3 peakDirection(const LobeSurface& s) {
    glm::vec3 best(0.0f);
    auto consider = [&](const std::vector<glm::vec3>& curve) {
        for (const glm::vec3& p : curve)
            if (glm::length(p) > glm::length(best)) best = p;
    };
    for (const auto& c : s.rings) consider(c);
    for (const auto& c : s.meridians) consider(c);
    consider(s.planeOfIncidence);
    return glm::normalize(best);
}

double angleDeg(const glm::vec3& a, const glm::vec3& b) {
    return std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0)) * 180.0 / kPi;
}

}  // namespace

TEST(LobePlot, SamplesAreThePhongAndBlinnPhongLobesInThePlane) {
    const LightingEnvironment env;  // heuristic lobes, no Fresnel
    for (float ke : {1.0f, 8.0f, 32.0f, 1000.0f})
        for (float incidence : {0.0f, 30.0f, 45.0f, 70.0f}) {
            const std::vector<LobeSample> samples = sampleLobe(env, ke, incidence);
            ASSERT_GT(samples.size(), 181u);
            EXPECT_FLOAT_EQ(samples.front().angleDeg, -90.0f);
            EXPECT_FLOAT_EQ(samples.back().angleDeg, 90.0f);
            for (std::size_t k = 0; k < samples.size(); ++k) {
                const LobeSample& s = samples[k];
                if (k > 0) {
                    ASSERT_GT(s.angleDeg, samples[k - 1].angleDeg);
                }
                const double delta = rad(double(s.angleDeg) - double(incidence));  // V's angle from R
                const std::string at = "k_e " + std::to_string(ke) + ", theta_i " + std::to_string(incidence) +
                                       ", V at " + std::to_string(s.angleDeg);
                expectClose(s.phong, std::pow(std::max(0.0, std::cos(delta)), double(ke)), "Phong, " + at);
                expectClose(s.blinnPhong, std::pow(std::cos(delta / 2.0), double(ke)), "Blinn-Phong, " + at);
            }
        }
}

// Both lobes peak at 1 exactly where V = R (in this plane H = N there), for every incidence.
TEST(LobePlot, BothLobesPeakAlongTheMirrorDirection) {
    for (float incidence : {0.0f, 20.0f, 45.0f, 80.0f}) {
        const std::vector<LobeSample> s = sampleLobe(LightingEnvironment{}, 64.0f, incidence);
        const auto phongPeak = std::max_element(s.begin(), s.end(), [](auto& a, auto& b) { return a.phong < b.phong; });
        const auto blinnPeak =
            std::max_element(s.begin(), s.end(), [](auto& a, auto& b) { return a.blinnPhong < b.blinnPhong; });
        EXPECT_FLOAT_EQ(phongPeak->angleDeg, incidence);
        EXPECT_FLOAT_EQ(blinnPeak->angleDeg, incidence);
        EXPECT_NEAR(phongPeak->phong, 1.0f, 1e-5f);
        EXPECT_NEAR(blinnPeak->blinnPhong, 1.0f, 1e-5f);
    }
}

// Energy normalisation multiplies spec by (k_e + 2) / 34 (Phong) and (k_e + 8) / 40 (Blinn-Phong), as
// the README states; Fresnel then weights each V by F(V.H), here Schlick at V = R where V.H = cos theta_i.
TEST(LobePlot, EnergyNormalisationAndFresnelScaleTheLobes) {
    LightingEnvironment env;
    env.normalization = SpecularNormalization::Energy;
    const std::vector<LobeSample> s = sampleLobe(env, 128.0f, 45.0f);
    const auto atR = std::find_if(s.begin(), s.end(), [](auto& x) { return x.angleDeg == 45.0f; });
    ASSERT_NE(atR, s.end());
    EXPECT_NEAR(atR->phong, 130.0 / 34.0, 1e-4);
    EXPECT_NEAR(atR->blinnPhong, 136.0 / 40.0, 1e-4);

    env.fresnel = FresnelMode::Schlick;
    env.ior = 1.5f;
    const std::vector<LobeSample> f = sampleLobe(env, 128.0f, 45.0f);
    const auto fAtR = std::find_if(f.begin(), f.end(), [](auto& x) { return x.angleDeg == 45.0f; });
    const double r0 = 0.04, schlick = r0 + (1.0 - r0) * std::pow(1.0 - std::cos(rad(45.0)), 5.0);
    EXPECT_NEAR(fAtR->phong, 130.0 / 34.0 * schlick, 1e-4);
}

// The plot's curves are spec * (sin phi, cos phi); the outer ring reaches the higher peak with a round
// value; N, I and R point where the lecture's figure has them.
TEST(LobePlot, PolylinesAreTheSamplesInPolarForm) {
    LightingEnvironment env;
    env.model = ReflectionModel::Phong;
    const float incidence = 30.0f;
    const Plot plot = lobePlot(env, 32.0f, incidence);
    const std::vector<LobeSample> s = sampleLobe(env, 32.0f, incidence);
    const PlotPolyline& phong = lineNamed(plot, "Phong");
    const PlotPolyline& blinn = lineNamed(plot, "Blinn-Phong");
    EXPECT_NE(phong.name.find("(in use)"), std::string::npos);
    EXPECT_EQ(blinn.name.find("(in use)"), std::string::npos);
    ASSERT_EQ(phong.points.size(), s.size());
    for (std::size_t k = 0; k < s.size(); ++k) {
        const double a = rad(s[k].angleDeg);
        EXPECT_NEAR(phong.points[k].x, s[k].phong * std::sin(a), 1e-6);
        EXPECT_NEAR(phong.points[k].y, s[k].phong * std::cos(a), 1e-6);
        EXPECT_NEAR(blinn.points[k].x, s[k].blinnPhong * std::sin(a), 1e-6);
        EXPECT_NEAR(blinn.points[k].y, s[k].blinnPhong * std::cos(a), 1e-6);
    }
    EXPECT_NE(plot.title.find("k_e = 32"), std::string::npos) << plot.title;
    EXPECT_NE(plot.title.find("theta_i = 30 deg"), std::string::npos) << plot.title;

    const glm::vec2 n = lineNamed(plot, "N").points.back(), i = lineNamed(plot, "I").points.back(),
                    r = lineNamed(plot, "R").points.back();
    EXPECT_NEAR(glm::normalize(n).y, 1.0, 1e-6);
    EXPECT_NEAR(glm::normalize(i).x, -std::sin(rad(30.0)), 1e-6);
    EXPECT_NEAR(glm::normalize(i).y, std::cos(rad(30.0)), 1e-6);
    EXPECT_NEAR(glm::normalize(r).x, std::sin(rad(30.0)), 1e-6);
    EXPECT_NEAR(glm::normalize(r).y, std::cos(rad(30.0)), 1e-6);

    // Peak 1: rings at 0.25, 0.5, 0.75, 1. With energy normalisation at k_e = 512 the Phong peak is
    // 514 / 34 = 15.1: rings of 5 up to 20.
    float outer = 0.0f;
    for (const PlotPolyline& l : plot.lines)
        if (l.name == "grid" && l.points.size() > 2) outer = std::max(outer, glm::length(l.points.front()));
    EXPECT_NEAR(outer, 1.0f, 1e-6f);
    env.normalization = SpecularNormalization::Energy;
    const Plot energy = lobePlot(env, 512.0f, incidence);
    float energyOuter = 0.0f;
    for (const PlotPolyline& l : energy.lines)
        if (l.name == "grid" && l.points.size() > 2) energyOuter = std::max(energyOuter, glm::length(l.points.front()));
    EXPECT_NEAR(energyOuter, 20.0f, 1e-4f);
}

// A k_e = 10000 lobe is 1.35 degrees wide at half height (cos^k_e = 1/2 at 0.67 degrees from R): the
// dense samples around R resolve it with dozens of points.
TEST(LobePlot, ANarrowLobeIsResolved) {
    const std::vector<LobeSample> s = sampleLobe(LightingEnvironment{}, 10000.0f, 45.0f);
    const int aboveHalf = int(std::count_if(s.begin(), s.end(), [](auto& x) { return x.phong > 0.5f; }));
    EXPECT_GE(aboveHalf, 30);
}

namespace {
// The lecture's forms: R_par = tan^2(t1 - t3) / tan^2(t1 + t3), R_perp = sin^2(t1 - t3) / sin^2(t1 + t3),
// eta1 sin t1 = eta2 sin t3.
void lectureFresnel(double theta1, double eta1, double eta2, double& par, double& perp) {
    const double theta3 = std::asin(eta1 / eta2 * std::sin(theta1));
    par = std::pow(std::tan(theta1 - theta3) / std::tan(theta1 + theta3), 2.0);
    perp = std::pow(std::sin(theta1 - theta3) / std::sin(theta1 + theta3), 2.0);
}
}  // namespace

TEST(FresnelPlot, CurvesAreTheLecturesFormulas) {
    for (const auto& [eta1, eta2] : {std::pair{1.0f, 1.5f}, std::pair{1.0f, 2.4f}, std::pair{1.5f, 1.0f}}) {
        const Plot plot = fresnelPlot(eta1, eta2);
        const PlotPolyline& par = lineNamed(plot, "R_par");
        const PlotPolyline& perp = lineNamed(plot, "R_perp");
        const PlotPolyline& average = lineNamed(plot, "(R_par + R_perp) / 2");
        const PlotPolyline& schlick = lineNamed(plot, "Schlick");
        ASSERT_EQ(par.points.size(), schlick.points.size());
        const double critical = eta1 > eta2 ? std::asin(double(eta2) / double(eta1)) * 180.0 / kPi : 90.0;
        const double r0 = std::pow((double(eta1) - eta2) / (double(eta1) + eta2), 2.0);
        for (std::size_t k = 0; k < par.points.size(); ++k) {
            const double deg = par.points[k].x, t1 = rad(deg);
            const std::string at = std::to_string(eta1) + " -> " + std::to_string(eta2) + " at " + std::to_string(deg);
            EXPECT_NEAR(schlick.points[k].y, r0 + (1.0 - r0) * std::pow(1.0 - std::cos(t1), 5.0), 1e-5) << at;
            if (deg >= critical) {  // total internal reflection
                EXPECT_EQ(par.points[k].y, 1.0f) << at;
                EXPECT_EQ(perp.points[k].y, 1.0f) << at;
                continue;
            }
            double p = r0, s = r0;  // normal incidence: both are R0 (the quotients are 0/0 there)
            if (deg > 0.0) lectureFresnel(t1, eta1, eta2, p, s);
            // Near grazing and near the critical angle the float evaluation loses digits (1 - cos^2).
            const double tolerance = deg > 89.0 || critical - deg < 1.0 ? 2e-3 : 2e-5;
            EXPECT_NEAR(par.points[k].y, p, tolerance) << at;
            EXPECT_NEAR(perp.points[k].y, s, tolerance) << at;
            EXPECT_NEAR(average.points[k].y, (p + s) / 2.0, tolerance) << at;
        }
    }
}

TEST(FresnelPlot, NormalIncidenceGivesR0) {
    const std::vector<FresnelSample> s = sampleFresnel(1.0f, 1.33f);
    EXPECT_EQ(s.front().angleDeg, 0.0f);
    const double r0 = std::pow((1.0 - 1.33) / (1.0 + 1.33), 2.0);
    EXPECT_NEAR(s.front().exact.average, r0, 1e-6);
    EXPECT_NEAR(s.front().exact.parallel, r0, 1e-6);
    EXPECT_NEAR(s.front().exact.perpendicular, r0, 1e-6);
    EXPECT_NEAR(s.front().schlick, r0, 1e-6);
}

// R_par vanishes at Brewster's angle atan(eta2 / eta1), from either side, and the plot marks it.
TEST(FresnelPlot, RParIsZeroAtBrewstersAngle) {
    for (const auto& [eta1, eta2] : {std::pair{1.0f, 1.5f}, std::pair{1.5f, 1.0f}, std::pair{1.0f, 4.0f}}) {
        const double brewster = std::atan(double(eta2) / double(eta1)) * 180.0 / kPi;
        const std::vector<FresnelSample> s = sampleFresnel(eta1, eta2);
        const auto lowest = std::min_element(s.begin(), s.end(), [](auto& a, auto& b) { return a.exact.parallel < b.exact.parallel; });
        EXPECT_NEAR(lowest->angleDeg, brewster, 1e-4) << eta1 << " -> " << eta2;
        EXPECT_LT(lowest->exact.parallel, 1e-6f);
        EXPECT_GT(lowest->exact.perpendicular, 0.01f);  // R_perp does not vanish: reflected light is polarised
        const Plot plot = fresnelPlot(eta1, eta2);
        const PlotPolyline& marker = lineNamed(plot, "Brewster");
        EXPECT_NEAR(marker.points.front().x, brewster, 1e-4);
    }
}

// From the denser medium, everything past asin(eta2 / eta1) is reflected; the plot marks that angle.
// Into the denser medium there is no critical angle and no marker.
TEST(FresnelPlot, CriticalAngleFromInside) {
    const double critical = std::asin(1.0 / 1.5) * 180.0 / kPi;  // 41.81 degrees
    ASSERT_TRUE(criticalAngleDeg(1.5f, 1.0f).has_value());
    EXPECT_NEAR(*criticalAngleDeg(1.5f, 1.0f), critical, 1e-4);
    EXPECT_FALSE(criticalAngleDeg(1.0f, 1.5f).has_value());
    EXPECT_FALSE(criticalAngleDeg(1.5f, 1.5f).has_value());

    const Plot inside = fresnelPlot(1.5f, 1.0f);
    const PlotPolyline& marker = lineNamed(inside, "critical angle");
    EXPECT_NEAR(marker.points.front().x, critical, 1e-4);
    EXPECT_NEAR(marker.points.back().x, critical, 1e-4);
    EXPECT_TRUE(marker.inLegend);
    EXPECT_NE(marker.name.find("41.8"), std::string::npos) << marker.name;
    for (const FresnelSample& s : sampleFresnel(1.5f, 1.0f)) {
        EXPECT_EQ(s.exact.totalInternal, s.angleDeg >= critical - 1e-4) << s.angleDeg;
        if (s.angleDeg < critical - 1e-3) {
            EXPECT_LT(s.exact.average, 1.0f) << s.angleDeg;
        }
    }
    EXPECT_FALSE(hasLineNamed(fresnelPlot(1.0f, 1.5f), "critical angle"));
}

TEST(ScenePlot, TakesTheScenesParameters) {
    Scene scene;
    scene.ior = 1.8f;
    scene.reflection = ReflectionModel::BlinnPhong;
    Material m;
    m.ke = 200.0f;
    const Plot lobe = scenePlot(PlotKind::Lobe, scene, m, PlotSettings{60.0f, false, {}, {}});
    EXPECT_NE(lobe.title.find("k_e = 200"), std::string::npos) << lobe.title;
    EXPECT_NE(lobe.title.find("theta_i = 60 deg"), std::string::npos) << lobe.title;
    EXPECT_NE(lineNamed(lobe, "Blinn-Phong").name.find("(in use)"), std::string::npos);
    const Plot outside = scenePlot(PlotKind::Fresnel, scene, m, PlotSettings{45.0f, false, {}, {}});
    EXPECT_NE(outside.title.find("eta_1 = 1.00 -> eta_2 = 1.80"), std::string::npos) << outside.title;
    const Plot inside = scenePlot(PlotKind::Fresnel, scene, m, PlotSettings{45.0f, true, {}, {}});
    EXPECT_NE(inside.title.find("eta_1 = 1.80 -> eta_2 = 1.00"), std::string::npos) << inside.title;
    EXPECT_TRUE(hasLineNamed(inside, "critical angle"));
}

// Every label, header line and legend entry lies inside the image at the sizes --plot allows, and the
// polar plot keeps its circles round.
TEST(PlotLayout, EverythingFitsAndCirclesStayRound) {
    // A font of fixed-width 6-pixel characters, 9 pixels tall (stb_easy_font at scale 1 is close).
    const MeasureText measure = [](const std::string& t) { return glm::vec2(6.0f * float(t.size()), 9.0f); };
    LightingEnvironment env;
    env.normalization = SpecularNormalization::Energy;
    env.fresnel = FresnelMode::Exact;
    Material anisotropic;
    anisotropic.anisotropic = true;
    anisotropic.anisotropy = {4.0f, 400.0f};
    for (const Plot& plot : {lobePlot(env, 32.0f, 45.0f), fresnelPlot(1.5f, 1.0f), lobe3dPlot(Material{}, env, 45.0f),
                             lobe3dPlot(anisotropic, env, 45.0f), brdfSlicePlot(Material{}, env, 45.0f),
                             brdfSlicePlot(anisotropic, env, 45.0f)})
        for (const glm::vec2 size : {glm::vec2(320, 240), glm::vec2(800, 600), glm::vec2(1600, 500)}) {
            const PlotLayout l = layoutPlot(plot, size, 10.0f, measure);
            const std::string what = std::string(toString(plot.kind)) + " at " + std::to_string(int(size.x)) + "x" +
                                     std::to_string(int(size.y));
            auto inside = [&](glm::vec2 lo, glm::vec2 hi) {
                return lo.x >= 0.0f && lo.y >= 0.0f && hi.x <= size.x && hi.y <= size.y;
            };
            for (const PlotLabel& label : plot.labels) {
                const glm::vec2 at = l.labelAt(label, measure(label.text));
                EXPECT_TRUE(inside(at, at + measure(label.text))) << what << ": " << label.text;
            }
            for (const PlotLayout::Line& line : l.header)
                EXPECT_TRUE(inside(line.at, line.at + measure(line.text))) << what << ": " << line.text;
            for (const PlotLegendEntry& e : l.legend)
                EXPECT_TRUE(inside(e.swatchFrom, e.textAt + measure(plot.lines[e.line].name))) << what;
            EXPECT_TRUE(inside(l.areaMin, l.areaMax)) << what;
            EXPECT_GT(l.areaMax.y - l.areaMin.y, 0.3f * size.y) << what << ": the plot area is squeezed";
            EXPECT_NEAR(l.toPixels(plot.min).x, l.areaMin.x, 1e-3) << what;
            EXPECT_NEAR(l.toPixels(plot.max).y, l.areaMin.y, 1e-3) << what;
            if (plot.equalAspect) {
                EXPECT_EQ(l.pixelsPerUnit.x, l.pixelsPerUnit.y) << what;
            }
        }
}

// The painters write each wrapped header line through lectureNotation, which makes " deg" a degree sign
// only where the space and the unit share a line: the viewer's 3-D lobe title read "theta_i = 56.9" and
// then "deg, Phong k_e = 16" at some panel widths. At every width the unit stays with its value, and
// the lines still make up the whole title.
TEST(PlotLayout, WrappingKeepsDegreesWithTheirValue) {
    const MeasureText measure = [](const std::string& t) { return glm::vec2(6.0f * float(t.size()), 9.0f); };
    const Plot plot = lobe3dPlot(Material{}, LightingEnvironment{}, 56.9f);
    ASSERT_NE(plot.title.find("56.9 deg,"), std::string::npos) << plot.title;
    for (int width = 120; width <= 700; ++width) {
        const PlotLayout l = layoutPlot(plot, glm::vec2(float(width), 600.0f), 10.0f, measure);
        std::string title;  // the title's lines (kPlotText; the subtitle's are kPlotAxis)
        for (const PlotLayout::Line& line : l.header) {
            EXPECT_NE(line.text.rfind("deg", 0), 0u) << width << ": " << line.text;
            if (line.color.r == kPlotText.r) title += (title.empty() ? "" : " ") + line.text;
        }
        EXPECT_EQ(title, plot.title) << width;
    }
}

TEST(PlotLayout, DashesCoverTheirShareOfTheLine) {
    const std::vector<glm::vec2> polyline = {{0, 0}, {103, 0}, {103, 47}};  // 150 pixels long
    const auto dashes = dashPolyline(polyline, 6.0f, 4.0f);
    float drawn = 0.0f;
    for (const auto& d : dashes) {
        float length = 0.0f;
        for (std::size_t k = 1; k < d.size(); ++k) length += glm::length(d[k] - d[k - 1]);
        EXPECT_LE(length, 6.0f + 1e-3f);
        drawn += length;
    }
    EXPECT_EQ(dashes.size(), 15u);                // 15 periods of 10 pixels
    EXPECT_NEAR(drawn, 150.0f * 0.6f, 1e-2f);
    ASSERT_EQ(dashes[10].size(), 3u);            // the dash over the corner (100..106) bends with it
    EXPECT_NEAR(dashes[10][1].x, 103.0f, 1e-4f);
    EXPECT_NEAR(dashes[10][1].y, 0.0f, 1e-4f);
}

// The PNGs --plot writes, against goldens that were looked at. The rasteriser is plain float code, so
// the same build reproduces them exactly; the tolerance (the golden tests' defaults) absorbs another
// compiler's rounding of a few edge pixels. SHADELAB_UPDATE_GOLDENS=1 rewrites them.
TEST(PlotGolden, LobeFresnelAndBrdf) {
    LightingEnvironment env;
    const std::pair<std::string, Plot> cases[] = {{"plot_lobe", lobePlot(env, 32.0f, 45.0f)},
                                                  {"plot_fresnel_inside", fresnelPlot(1.5f, 1.0f)},
                                                  {"plot_lobe3d", lobe3dPlot(Material{}, modelEnv(ReflectionModel::Phong), 60.0f)},
                                                  {"plot_brdf_slice", brdfSlicePlot(anisotropicMaterial(8.0f, 128.0f), env, 45.0f)}};
    for (const auto& [name, plot] : cases) {
        const Image actual = renderPlotImage(plot, 640, 480);
        const std::string golden = std::string(SHADELAB_SOURCE_DIR) + "/tests/golden/" + name + ".png";
        if (std::getenv("SHADELAB_UPDATE_GOLDENS")) {
            writePng(golden, actual, 9);
            continue;
        }
        const Image expected = readPng(golden);
        const ImageTolerance tolerance = toleranceWithShare(expected.width, expected.height);
        const CompareResult r = tolerance.compare(actual, expected);
        if (!tolerance.matches(r)) {
            const std::filesystem::path out = SHADELAB_TEST_OUTPUT_DIR;
            std::filesystem::create_directories(out);
            writePng((out / (name + ".actual.png")).string(), actual);
            writePng((out / (name + ".diff.png")).string(), differenceImage(actual, expected, tolerance.pixelThreshold));
        }
        EXPECT_TRUE(tolerance.matches(r)) << name << ": " << describe(r, tolerance) << " (actual and diff in "
                                          << SHADELAB_TEST_OUTPUT_DIR << ")";
    }
}

// f_r is core/shading's: brdf() against the formula written out, k_d + k_s spec / (N.I), and the
// renderer's own shade() for one directional light of radiance 1 with white colours.
TEST(BrdfPlot, FrIsTheRenderersFormula) {
    Material m;
    m.color = m.specularColor = glm::vec3(1.0f);
    m.ka = 0.0f;
    m.kd = 0.2f;  // small weights: the shaded sum stays below 1 (no clamping)
    m.ks = 0.3f;
    LightingEnvironment env;
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    for (float thetaI : {10.0f, 45.0f, 70.0f})
        for (float thetaO : {0.0f, 30.0f, 60.0f})
            for (float dphi : {0.0f, 90.0f, 170.0f, 180.0f}) {
                const glm::vec3 i = directionAt(thetaI, 0.0f), v = directionAt(thetaO, dphi);
                const BrdfValue f = brdf(m, env, n, i, v, plotTangentFrame());
                expectClose(f.total(), m.kd + m.ks * specularTerm(env, m.ke, n, i, v) / std::cos(rad(thetaI)), "f_r");
                // The renderer: L_o = L (k_d (N.I) + k_s spec) = f_r E with E = L (N.I), L = 1.
                Light light;
                light.type = LightType::Directional;
                light.direction = -i;
                light.color = glm::vec3(1.0f);
                light.intensity = 1.0f;
                env.lights = {light};
                env.eyeWorld = 10.0f * v;
                const glm::vec3 shaded = shade(m, env, glm::vec3(0.0f), n);
                expectClose(shaded.x, f.total() * std::cos(rad(thetaI)), "shade()");
            }
}

// The surface's peak lies along R = 2(N.I)N - I for Phong; for Blinn-Phong where the half vector
// H = normalize(I + V) is N (the same direction R); with and without anisotropy.
TEST(BrdfPlot, Lobe3dPeaksAlongTheMirrorDirection) {
    for (float incidence : {0.0f, 30.0f, 60.0f})
        for (float ke : {8.0f, 32.0f, 500.0f}) {
            Material m;
            m.ke = ke;
            const std::string at = "theta_i " + std::to_string(incidence) + ", k_e " + std::to_string(ke);
            const LobeSurface phong = sampleLobeSurface(m, modelEnv(ReflectionModel::Phong), incidence);
            const glm::vec3 r = 2.0f * glm::dot(glm::vec3(0, 1, 0), phong.i) * glm::vec3(0, 1, 0) - phong.i;
            EXPECT_LT(angleDeg(peakDirection(phong), r), 0.5) << "Phong, " << at;
            const LobeSurface blinn = sampleLobeSurface(m, modelEnv(ReflectionModel::BlinnPhong), incidence);
            const glm::vec3 h = glm::normalize(blinn.i + peakDirection(blinn));
            EXPECT_LT(angleDeg(h, glm::vec3(0, 1, 0)), 0.5) << "Blinn-Phong, " << at;
            const LobeSurface aniso = sampleLobeSurface(anisotropicMaterial(ke, 4.0f * ke), modelEnv(ReflectionModel::BlinnPhong), incidence);
            EXPECT_LT(angleDeg(glm::normalize(aniso.i + peakDirection(aniso)), glm::vec3(0, 1, 0)), 0.5) << "anisotropic, " << at;
            // The peak's value is f_r there: k_d + k_s / cos theta_i.
            expectClose(phong.peak, m.kd + m.ks / std::cos(rad(incidence)), "peak, " + at);
        }
}

// The pictures follow k_e and anisotropy: a narrower lobe, an elongated one; k_t = k_b is Blinn-Phong's.
TEST(BrdfPlot, PlotsChangeWithKeAndAnisotropy) {
    const LightingEnvironment env = modelEnv(ReflectionModel::BlinnPhong);
    Material m8, m64;
    m8.ke = 8.0f;
    m64.ke = 64.0f;
    EXPECT_NE(allPoints(lobe3dPlot(m8, env, 45.0f)), allPoints(lobe3dPlot(m64, env, 45.0f)));
    EXPECT_NE(sampleAzimuthSlice(m8, env, 45.0f, 0.0f).values, sampleAzimuthSlice(m64, env, 45.0f, 0.0f).values);
    EXPECT_NE(sampleIncidencePlane(m8, env, 0.0f).values, sampleIncidencePlane(m64, env, 0.0f).values);

    // k_t != k_b: another surface than k_t = k_b, and a delta_phi slice that is not symmetric about the
    // plane of incidence once the light is off the tangent's axis... and one that differs between phi_i = 0 and 90.
    const Material iso = anisotropicMaterial(32.0f, 32.0f), aniso = anisotropicMaterial(8.0f, 256.0f);
    const LobeSurface sIso = sampleLobeSurface(iso, env, 45.0f), sAniso = sampleLobeSurface(aniso, env, 45.0f);
    EXPECT_NE(sIso.rings, sAniso.rings);
    const BrdfSliceGrid a0 = sampleAzimuthSlice(aniso, env, 45.0f, 0.0f), a90 = sampleAzimuthSlice(aniso, env, 45.0f, 90.0f);
    double largest = 0.0;
    for (std::size_t k = 0; k < a0.values.size(); ++k) largest = std::max(largest, std::abs(double(a0.values[k]) - a90.values[k]));
    EXPECT_GT(largest, 0.1) << "phi_i = 0 and 90 deg give the same slice";
    const BrdfSliceGrid slanted = sampleAzimuthSlice(aniso, env, 45.0f, 30.0f);
    double asymmetry = 0.0;
    for (int row = 0; row < slanted.rows; ++row)
        for (int c = 0; c < slanted.columns; ++c)
            asymmetry = std::max(asymmetry, std::abs(double(slanted.at(c, row)) - slanted.at(slanted.columns - 1 - c, row)));
    EXPECT_GT(asymmetry, 0.1) << "k_t != k_b at phi_i = 30 deg: the slice is not symmetric in delta_phi";

    // k_t = k_b: the same BRDF at every phi_i, symmetric in delta_phi about 180 deg, and Blinn-Phong's values.
    Material blinn;
    blinn.ke = 32.0f;
    const BrdfSliceGrid b = sampleAzimuthSlice(blinn, env, 45.0f, 0.0f);
    for (float phi : {0.0f, 30.0f, 90.0f}) {
        const BrdfSliceGrid g = sampleAzimuthSlice(iso, env, 45.0f, phi);
        for (int row = 0; row < g.rows; ++row)
            for (int c = 0; c < g.columns; ++c) {
                EXPECT_NEAR(g.at(c, row), g.at(g.columns - 1 - c, row), 1e-4f * (1.0f + g.at(c, row)))
                    << "phi_i " << phi << ", column " << c << ", row " << row;
                EXPECT_NEAR(g.at(c, row), b.at(c, row), 1e-3f * (1.0f + b.at(c, row))) << "phi_i " << phi;
            }
    }
}

// The isotropic plot has one row of panels (two heat maps, each with its colour bar), the anisotropic one two,
// and the incidence plane's ridge is R: theta_o = theta_i on the mirror side.
TEST(BrdfPlot, SlicePanelsAndTheMirrorRidge) {
    const LightingEnvironment env = modelEnv(ReflectionModel::Phong);
    Material m;
    m.ke = 200.0f;
    EXPECT_EQ(brdfSlicePlot(m, env, 45.0f).heatMaps.size(), 4u);  // two panels, two colour bars
    EXPECT_EQ(brdfSlicePlot(anisotropicMaterial(8.0f, 64.0f), modelEnv(ReflectionModel::BlinnPhong), 45.0f).heatMaps.size(), 6u);
    const BrdfSliceGrid g = sampleIncidencePlane(m, env, 0.0f);
    for (int c = 0; c < g.columns; c += 10) {
        int best = 0;
        for (int row = 0; row < g.rows; ++row)
            if (g.at(c, row) > g.at(c, best)) best = row;
        EXPECT_EQ(best, 90 + c) << "theta_i " << c + 0.5;  // row 90 + c holds theta_o = c + 0.5
    }
    const Plot p = scenePlot(PlotKind::BrdfSlice, Scene{}, m, PlotSettings{30.0f, false, {}, {}});
    EXPECT_NE(p.title.find("f_r(delta_phi; theta_i -> theta_o)"), std::string::npos) << p.title;
    EXPECT_EQ(lectureNotation("delta_phi, phi_i, omega_o"), "\u0394\u03c6, \u03c6_i, \u03c9_o");
    // Captions (the viewer's and the web page's) too: a name that ends a word, not a word's start.
    EXPECT_EQ(lectureNotation("eta_i sin theta_i = eta_t sin theta_t, 90 deg, 45 degrees"),
              "\u03b7_i sin \u03b8_i = \u03b7_t sin \u03b8_t, 90\u00b0, 45 degrees");
}

// The viewer turns the 3-D lobe through PlotSettings::lobeView; the default is the PNG's view, and a
// view from straight above (elevation 89) sees N end-on: its arrow projects to (almost) a point.
TEST(BrdfPlot, Lobe3dViewTurns) {
    Scene scene;
    Material m;
    PlotSettings settings;
    const Plot fixed = scenePlot(PlotKind::Lobe3d, scene, m, settings);
    EXPECT_EQ(allPoints(fixed), allPoints(lobe3dPlot(m, lightingEnvironment(scene), settings.incidenceDeg)));
    settings.lobeView.azimuthDeg = 30.0f;
    EXPECT_NE(allPoints(scenePlot(PlotKind::Lobe3d, scene, m, settings)), allPoints(fixed));
    const LobeView above{0.0f, 89.0f};
    EXPECT_LT(glm::length(lobe3dProjection(glm::vec3(0.0f, 1.0f, 0.0f), above)), 0.02f);
    EXPECT_NEAR(glm::length(lobe3dProjection(glm::vec3(1.0f, 0.0f, 0.0f), above)), 1.0f, 1e-3f);
}

// The viewer's 3-D lobe at a probed point (PlotSettings::probed, from lobeIncidenceAt): the point's own
// N, I and V in any orientation give the plot's frame the same angles; an anisotropic point's light
// keeps its azimuth between T and B; a light behind the surface gives no lobe.
TEST(BrdfPlot, Lobe3dFollowsAProbedPoint) {
    const LightingEnvironment env = modelEnv(ReflectionModel::BlinnPhong);
    // A tilted surface point: N, with I 35 deg from it and V 50 deg from it on another side.
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f));
    const glm::vec3 across = glm::normalize(glm::cross(n, glm::vec3(0.0f, 0.0f, 1.0f)));
    const glm::vec3 other = glm::cross(n, across);
    const glm::vec3 i = float(std::cos(rad(35.0))) * n + float(std::sin(rad(35.0))) * across;
    const glm::vec3 v = glm::normalize(float(std::cos(rad(50.0))) * n + float(std::sin(rad(50.0))) * (0.6f * across + 0.8f * other));
    const std::optional<LobeIncidence> li = lobeIncidenceAt(n, i, v, nullptr);
    ASSERT_TRUE(li.has_value());
    EXPECT_LT(angleDeg(li->toLight, directionAt(35.0f, 180.0f)), 0.01) << "isotropic: I on the left, 35 deg from N";
    ASSERT_TRUE(li->toEye.has_value());
    expectClose(glm::dot(*li->toEye, glm::vec3(0, 1, 0)), glm::dot(v, n), "N.V");
    expectClose(glm::dot(*li->toEye, li->toLight), glm::dot(v, i), "I.V");
    // The probed plot is the slider's plot at that angle, plus V and the place in the title.
    Material m;
    Scene scene;
    PlotSettings settings;
    settings.probed = *li;
    settings.probed->where = "at pixel 10, 20";
    const Plot probed = scenePlot(PlotKind::Lobe3d, scene, m, settings);
    EXPECT_NE(probed.title.find("at pixel 10, 20: theta_i = 35 deg"), std::string::npos) << probed.title;
    EXPECT_EQ(std::count_if(probed.lines.begin(), probed.lines.end(), [](const PlotPolyline& l) { return l.name == "V"; }), 1);
    const LobeSurface s = sampleLobeSurface(m, env, li->toLight), slider = sampleLobeSurface(m, env, 35.0f);
    expectClose(s.peak, slider.peak, "peak");
    EXPECT_LT(angleDeg(s.r, slider.r), 0.01);

    // Anisotropic: the point's T and B are the plot's; the light 30 deg round from T toward B.
    const TangentFrame frame{across, other};  // B = N x T here
    const glm::vec3 i2 = float(std::cos(rad(40.0))) * n + float(std::sin(rad(40.0))) * (float(std::cos(rad(30.0))) * across + float(std::sin(rad(30.0))) * other);
    const std::optional<LobeIncidence> a = lobeIncidenceAt(n, i2, v, &frame);
    ASSERT_TRUE(a.has_value());
    EXPECT_LT(angleDeg(a->toLight, directionAt(40.0f, 30.0f)), 0.01) << "B is at phi = 90 deg: 30 deg round from T toward B";
    const Material aniso = anisotropicMaterial(8.0f, 256.0f);
    const Plot turned = lobe3dPlot(aniso, env, *a);
    EXPECT_NE(turned.title.find("theta_i = 40 deg, phi_i = 30 deg"), std::string::npos) << turned.title;
    EXPECT_NE(allPoints(turned), allPoints(lobe3dPlot(aniso, env, lobeIncidence(40.0f))));
    // Peak along H = N, as for the slider's lobe.
    const LobeSurface sa = sampleLobeSurface(aniso, env, a->toLight);
    EXPECT_LT(angleDeg(glm::normalize(sa.i + peakDirection(sa)), glm::vec3(0, 1, 0)), 0.5);

    EXPECT_FALSE(lobeIncidenceAt(n, -i, v, nullptr).has_value()) << "light behind the surface";
}
