#pragma once
// The lecture's plots, GL-free:
//  - the specular lobe in the plane of incidence: spec as a function of the view direction V, for
//    Phong and Blinn-Phong at the scene's k_e, with the incoming direction I, the normal N and the
//    mirror direction R marked;
//  - the Fresnel reflectance over the angle of incidence: R_par, R_perp, their average (unpolarised
//    light) and Schlick's approximation, with the critical angle marked when eta1 > eta2;
//  - the BRDF as a function: f_r(omega_i -> omega_o) for one light direction as a 3-D polar
//    surface over the hemisphere (lobe3d), and heat maps of the isotropic BRDF's parameterisation
//    f_r(delta_phi; theta_i -> theta_o) (brdf-slice). Their f_r is core/shading's brdf().
// The values come from core/shading/lighting (specularTerm, fresnelExact, fresnelSchlick), so the plots show
// exactly what the renderer computes. A Plot is a small display list in plot coordinates — polylines
// and labels, a title and a legend — and layoutPlot maps it onto a pixel rectangle; plot_image.cpp
// rasterises it into a PNG (--plot), the viewer's panel draws the same Plot with ImGui.
#include "core/image/text.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/scene_names.hpp"
#include "core/shading/lighting.hpp"

#include <glm/vec2.hpp>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shadelab {

enum class PlotKind { Lobe, Fresnel, Lobe3d, BrdfSlice };
inline constexpr EnumName<PlotKind> kPlotKindNames[] = {{"lobe", PlotKind::Lobe},
                                                        {"fresnel", PlotKind::Fresnel},
                                                        {"lobe3d", PlotKind::Lobe3d},
                                                        {"brdf-slice", PlotKind::BrdfSlice}};
const char* toString(PlotKind kind);

// ---- The curves' values

// In the plane of incidence, with N = +y, the incoming light at incidenceDeg from N on the left
// (I = (-sin, cos), pointing toward the light, as in the lecture's R(I) = 2(N.I)N - I) and the view
// direction V at angleDeg from N, positive toward R's side (V = (sin, cos)): spec for each model.
struct LobeSample {
    float angleDeg = 0.0f;    // V's angle from N, -90..90
    float phong = 0.0f;       // specularTerm with env.model = Phong
    float blinnPhong = 0.0f;  // specularTerm with env.model = BlinnPhong
};
// V from -90 to 90 degrees: every degree, and densely around R (where a high k_e's lobe is narrower
// than a degree), in increasing angle. env supplies normalisation, Fresnel and ior (its model is ignored).
std::vector<LobeSample> sampleLobe(const LightingEnvironment& env, float ke, float incidenceDeg);

struct FresnelSample {
    float angleDeg = 0.0f;  // angle of incidence theta_1, 0..90
    FresnelTerms exact;     // fresnelExact(cos theta_1, eta1, eta2)
    float schlick = 0.0f;   // fresnelSchlick(cos theta_1, eta1, eta2)
};
// 0 to 90 degrees every quarter degree, plus the critical and Brewster angles exactly, in increasing angle.
std::vector<FresnelSample> sampleFresnel(float eta1, float eta2);

// asin(eta2 / eta1) in degrees when eta1 > eta2 (total internal reflection beyond it), else none.
std::optional<float> criticalAngleDeg(float eta1, float eta2);
// atan(eta2 / eta1) in degrees: R_par is 0 there (Brewster's angle).
float brewsterAngleDeg(float eta1, float eta2);

// ---- The display list

// A polyline in plot coordinates. `width` is in line units (the renderer's base line width: about
// 1.25 pixels in an 800 x 600 PNG); curves are 2, grid lines 1.
struct PlotPolyline {
    std::string name;  // the legend text, or what the line is ("grid", "N", "critical angle")
    std::vector<glm::vec2> points;
    Rgba8 color;
    float width = 1.0f;
    bool dashed = false;
    bool arrow = false;  // an arrowhead at the last point
    bool inLegend = false;
};

// Text anchored at a point in plot coordinates: `align` (0, 0) puts the text's top-left corner there,
// (0.5, 1) its bottom centre; `offset` then moves it by that many line heights (x right, y down).
struct PlotLabel {
    glm::vec2 at{0.0f};
    std::string text;  // printable ASCII (the PNG font has no Greek)
    glm::vec2 align{0.0f};
    glm::vec2 offset{0.0f};
    Rgba8 color;
};

// A grid of coloured cells over a rectangle of plot coordinates (a heat map): `columns` x `rows` cells,
// row-major, row 0 at min.y. Painted before the lines, without antialiasing between cells.
struct PlotHeatMap {
    glm::vec2 min{0.0f}, max{1.0f};
    int columns = 0, rows = 0;
    std::vector<Rgba8> cells;
};

struct Plot {
    PlotKind kind = PlotKind::Fresnel;
    std::string title;                // what is plotted, for which parameters (the layout wraps it)
    std::string subtitle;             // how to read it: the radius, R0, the normalisation
    glm::vec2 min{0.0f}, max{1.0f};   // the rectangle of plot coordinates that is shown
    bool equalAspect = false;         // one unit spans as many pixels along x as along y (polar plots)
    std::vector<PlotPolyline> lines;  // in drawing order: grid first, curves last
    std::vector<PlotLabel> labels;
    std::vector<PlotHeatMap> heatMaps;  // under the lines
};

// The colours, for a dark background (the viewer's panel, and the PNG, as the sweep sheets: both read
// well on a projector). Curve colours are from Okabe and Ito's colour-blind-safe palette, lightened.
inline constexpr Rgba8 kPlotBackground{30, 30, 34, 255};
inline constexpr Rgba8 kPlotText{235, 235, 235, 255};
inline constexpr Rgba8 kPlotGrid{80, 80, 88, 255};
inline constexpr Rgba8 kPlotAxis{170, 170, 175, 255};

// The lobe for the scene's normalisation, Fresnel mode and ior, at exponent ke and the given incidence
// (0..89 degrees). Radius = spec (without k_s, S and the light): with energy normalisation that includes
// the renderer's factor energySpecularScale, with Fresnel the weight F(V.H). Both lobes share one scale;
// the reference half circles are labelled with their spec value and the outer one reaches the higher
// peak. env.model, the scene's reflection model, is marked "(in use)" in the legend.
Plot lobePlot(const LightingEnvironment& env, float ke, float incidenceDeg);
// R_par, R_perp, their average and Schlick for light going from eta1 into eta2.
Plot fresnelPlot(float eta1, float eta2);

// ---- The BRDF plots
//
// Both work in the surface's own frame: N = +y, the tangent T = +x (phi = 0; where k_t applies) and the
// bitangent B = N x T = -z (k_b). A direction at (theta, phi) is (sin theta cos phi, cos theta, -sin theta sin phi).
// The value is brdf() of core/shading for the scene's model, normalisation and Fresnel mode and the
// material's k_d, k_s, k_e or anisotropy.
glm::vec3 directionAt(float thetaDeg, float phiDeg);
TangentFrame plotTangentFrame();

// The 3-D lobe for the light at (incidenceDeg, phi_i = 180 deg: I on the left, as in the lobe plot):
// the surface r(omega_o) = f_r(I -> omega_o) over the upper hemisphere as curves on a grid centred on
// the mirror direction R (rings at fixed angles from R, dense near R where the lobe is; and meridians
// through R), cut at the horizon; in 3-D plot-frame points (direction * f_r).
struct LobeSurface {
    glm::vec3 i{0.0f}, r{0.0f};  // unit: toward the light, its mirror direction
    std::vector<std::vector<glm::vec3>> rings, meridians;
    std::vector<glm::vec3> planeOfIncidence;  // the 2-D lobe: the surface cut by the x-y plane
    float peak = 0.0f;                        // the largest f_r on the surface
};
LobeSurface sampleLobeSurface(const Material& m, const LightingEnvironment& env, float incidenceDeg);
// The same for any light direction `toLight` (unit, in the plot's frame, above the surface: y > 0).
LobeSurface sampleLobeSurface(const Material& m, const LightingEnvironment& env, const glm::vec3& toLight);

// Where the light and the eye are for the 3-D lobe, in the plot's frame (N = +y, T = +x, B = -z). The
// PNG's: the light at the incidence angle on the left (phi_i = 180 deg), no eye. The viewer's, once a
// pixel is probed: that point's own I and V (lobeIncidenceAt).
struct LobeIncidence {
    glm::vec3 toLight{0.0f, 1.0f, 0.0f};  // omega_i, unit, y > 0
    std::optional<glm::vec3> toEye;       // V, unit (drawn when set)
    std::string where;                    // "at pixel 412, 300": said in the title when set
};
LobeIncidence lobeIncidence(float incidenceDeg);
// A surface point's N, I (toward the light) and V (toward the eye) in world space, into the plot's frame.
// Anisotropic (`frame` set): the point's T and B are the plot's T and B, so phi_i is where the light is
// between them. Isotropic: azimuth does not matter, and the frame is turned to put I on the left
// (phi_i = 180 deg), as in the PNG. None when the light is behind the surface (N.I <= 0): no lobe.
std::optional<LobeIncidence> lobeIncidenceAt(const glm::vec3& n, const glm::vec3& i, const glm::vec3& v,
                                             const TangentFrame* frame);
// Where the 3-D lobe is seen from: the eye's azimuth phi (from T, as directionAt) and elevation above
// the surface. The default is the PNG's fixed oblique view, from the front right, 25 degrees up; the
// viewer's Plots section turns it with the mouse.
struct LobeView {
    float azimuthDeg = -60.0f;
    float elevationDeg = 25.0f;  // 0..89
};
// The surface projected orthographically from `view`, with N, I, R (and T, B when anisotropic) and
// reference circles in the surface.
Plot lobe3dPlot(const Material& m, const LightingEnvironment& env, float incidenceDeg, const LobeView& view = {});
Plot lobe3dPlot(const Material& m, const LightingEnvironment& env, const LobeIncidence& incidence,
                const LobeView& view = {});
// The view: plot x = dot(p, right), plot y = dot(p, up).
glm::vec2 lobe3dProjection(const glm::vec3& p, const LobeView& view = {});

// Heat maps of f_r on a logarithmic colour scale (one for each kind of panel; in the plane of incidence
// its top is the largest value up to theta_i = 80 deg, beyond which f_r's 1 / (N.I) grows without bound):
//  - over (theta_i, theta_o) in the plane of incidence: theta_o from -90 (delta_phi = 0, the light's
//    side) through 0 to 90 (delta_phi = 180 deg, the mirror side, where theta_o = theta_i is R);
//  - over (delta_phi, theta_o) at theta_i = incidenceDeg, delta_phi = phi_o - phi_i from 0 to 360.
// Isotropic: one of each (phi_i = 0). Anisotropic: both at phi_i = 0 and at phi_i = 90 deg, one row
// each, which differ: the fourth angle.
struct BrdfSliceGrid {
    int columns = 0, rows = 0;
    std::vector<float> values;  // row-major, row 0 at the lowest theta_o
    float at(int column, int row) const {
        return values[std::size_t(row) * std::size_t(columns) + std::size_t(column)];
    }
};
BrdfSliceGrid sampleIncidencePlane(const Material& m, const LightingEnvironment& env,
                                   float phiIDeg);  // 90 x 180, 1 deg cells
BrdfSliceGrid sampleAzimuthSlice(const Material& m, const LightingEnvironment& env, float thetaIDeg,
                                 float phiIDeg);  // 180 x 90, 2 x 1 deg
Plot brdfSlicePlot(const Material& m, const LightingEnvironment& env, float incidenceDeg);
// The colour scale: t in [0, 1] to viridis (dark purple to yellow; readable on the dark background).
Rgba8 heatColor(float t);

// What the plots take beside the scene: the lobe's incoming direction, and which side of the surface
// the Fresnel plot's light comes from.
struct PlotSettings {
    float incidenceDeg = 45.0f;  // angle between I and N, 0..kIncidenceDegRange.hi
    bool fromInside = false;     // false: from air into the material (eta1 = 1, eta2 = ior), as the
                                 // renderer's Fresnel term; true: eta1 = ior, eta2 = 1 (total internal reflection)
    LobeView lobeView;           // the 3-D lobe's view (the CLI keeps the default)
    // The viewer with a probed pixel: the 3-D lobe of that point's own I and V (incidenceDeg is then
    // not used for it). The CLI leaves it unset.
    std::optional<LobeIncidence> probed;
};

// The plot for a scene: the lobe at material.ke with the scene's reflection model, normalisation,
// Fresnel mode and ior; the Fresnel curves for the scene's ior, from the side settings.fromInside says.
Plot scenePlot(PlotKind kind, const Scene& scene, const Material& material, const PlotSettings& settings);

// ---- Layout: shared by the PNG rasteriser and the panel

// Measures a single line of text in pixels (width, height).
using MeasureText = std::function<glm::vec2(const std::string&)>;

struct PlotLegendEntry {
    std::size_t line = 0;                        // index into Plot::lines
    glm::vec2 swatchFrom{0.0f}, swatchTo{0.0f};  // a short stroke in the line's style
    glm::vec2 textAt{0.0f};                      // top-left
};

// Where everything goes in a width x height pixel rectangle (origin top-left, y down): title and
// subtitle on top, the legend under them (wrapping), the plot area below with room for axis labels.
struct PlotLayout {
    struct Line {
        std::string text;
        glm::vec2 at{0.0f};  // top-left
        Rgba8 color;
    };
    std::vector<Line> header;  // title and subtitle, wrapped at spaces to fit the width
    std::vector<PlotLegendEntry> legend;
    glm::vec2 areaMin{0.0f}, areaMax{0.0f};  // the pixels that plot.min..max map onto
    float lineHeight = 0.0f;
    glm::vec2 pixelsPerUnit{1.0f};  // y is flipped: larger plot y is higher up
    glm::vec2 plotOrigin{0.0f};     // the pixel of plot point (0, 0)
    glm::vec2 toPixels(glm::vec2 p) const {
        return {plotOrigin.x + p.x * pixelsPerUnit.x, plotOrigin.y - p.y * pixelsPerUnit.y};
    }
    // A label's top-left pixel, given its measured size.
    glm::vec2 labelAt(const PlotLabel& label, glm::vec2 textSize) const;
};
PlotLayout layoutPlot(const Plot& plot, glm::vec2 size, float lineHeight, const MeasureText& measure);

// The plots' texts are written in ASCII (theta_i, eta_2, deg, ->, R_par); a TrueType font writes them as
// the lecture does: θ_i, η₂, °, →, R∥. The bitmap font of core/image/text.hpp has only ASCII.
std::string lectureNotation(std::string text);

// What a plot is drawn with: the PNG rasteriser (plot_image.cpp) and the viewer's ImGui draw list each
// implement these few primitives, and paintPlot does the rest the same way for both. Pixels are in
// the painter's own units, origin at the plot's top-left corner, y down.
class PlotPainter {
public:
    virtual ~PlotPainter() = default;
    virtual float lineHeight() const = 0;                          // of one line of text
    virtual glm::vec2 measure(const std::string& text) const = 0;  // one line: (width, height)
    // One polyline, `width` pixels wide, blended once (joints are not drawn twice).
    virtual void stroke(const std::vector<glm::vec2>& pixels, Rgba8 color, float width) = 0;
    virtual void fillTriangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, Rgba8 color) = 0;
    // An axis-aligned rectangle (a heat map's cell): neighbouring cells must meet without a seam. The
    // default is two triangles; painters that antialias triangles override it.
    virtual void fillRect(glm::vec2 lo, glm::vec2 hi, Rgba8 color) {
        fillTriangle(lo, {hi.x, lo.y}, hi, color);
        fillTriangle(lo, hi, {lo.x, hi.y}, color);
    }
    virtual void text(glm::vec2 topLeft, const std::string& text, Rgba8 color) = 0;
};
// Lays the plot out in `size` and paints lines, arrowheads, labels, title and legend (not the
// background). lineUnit: pixels per line unit (PlotPolyline::width); dashes and arrowheads scale with it.
PlotLayout paintPlot(const Plot& plot, glm::vec2 size, float lineUnit, PlotPainter& painter);

// The polyline in pixels cut into dashes (dash and gap lengths in pixels), for dashed lines.
std::vector<std::vector<glm::vec2>> dashPolyline(const std::vector<glm::vec2>& pixels, float dash, float gap);
// The two back corners of an arrowhead at `tip` coming from `from`, `length` pixels long.
std::pair<glm::vec2, glm::vec2> arrowHead(glm::vec2 from, glm::vec2 tip, float length);

}  // namespace shadelab
