#pragma once
// The lecture's two plots, GL-free (issue 6):
//  - the specular lobe in the plane of incidence: spec as a function of the view direction V, for
//    Phong and Blinn-Phong at the scene's k_e, with the incoming direction I, the normal N and the
//    mirror direction R marked;
//  - the Fresnel reflectance over the angle of incidence: R_par, R_perp, their average (unpolarised
//    light) and Schlick's approximation, with the critical angle marked when eta1 > eta2.
// The values come from core/shading/lighting (specularTerm, fresnelExact, fresnelSchlick), so the plots show
// exactly what the renderer computes. A Plot is a small display list in plot coordinates — polylines
// and labels, a title and a legend — and layoutPlot maps it onto a pixel rectangle; plot_image.cpp
// rasterises it into a PNG (--plot), the viewer's panel draws the same Plot with ImGui.
#include "core/shading/lighting.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/scene_names.hpp"
#include "core/image/text.hpp"

#include <glm/vec2.hpp>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shadelab {

enum class PlotKind { Lobe, Fresnel };
inline constexpr EnumName<PlotKind> kPlotKindNames[] = {{"lobe", PlotKind::Lobe}, {"fresnel", PlotKind::Fresnel}};
const char* toString(PlotKind kind);

// ---- The curves' values

// In the plane of incidence, with N = +y, the incoming light at incidenceDeg from N on the left
// (I = (-sin, cos), pointing toward the light, as in the lecture's R(I) = 2(N.I)N - I) and the view
// direction V at angleDeg from N, positive toward R's side (V = (sin, cos)): spec for each model.
struct LobeSample {
    float angleDeg = 0.0f;   // V's angle from N, -90..90
    float phong = 0.0f;      // specularTerm with env.model = Phong
    float blinnPhong = 0.0f; // specularTerm with env.model = BlinnPhong
};
// V from -90 to 90 degrees: every degree, and densely around R (where a high k_e's lobe is narrower
// than a degree), in increasing angle. env supplies normalisation, Fresnel and ior (its model is ignored).
std::vector<LobeSample> sampleLobe(const LightingEnvironment& env, float ke, float incidenceDeg);

struct FresnelSample {
    float angleDeg = 0.0f;   // angle of incidence theta_1, 0..90
    FresnelTerms exact;      // fresnelExact(cos theta_1, eta1, eta2)
    float schlick = 0.0f;    // fresnelSchlick(cos theta_1, eta1, eta2)
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
    std::string name;                 // the legend text, or what the line is ("grid", "N", "critical angle")
    std::vector<glm::vec2> points;
    Rgba8 color;
    float width = 1.0f;
    bool dashed = false;
    bool arrow = false;               // an arrowhead at the last point
    bool inLegend = false;
};

// Text anchored at a point in plot coordinates: `align` (0, 0) puts the text's top-left corner there,
// (0.5, 1) its bottom centre; `offset` then moves it by that many line heights (x right, y down).
struct PlotLabel {
    glm::vec2 at{0.0f};
    std::string text;                 // printable ASCII (the PNG font has no Greek)
    glm::vec2 align{0.0f};
    glm::vec2 offset{0.0f};
    Rgba8 color;
};

struct Plot {
    PlotKind kind = PlotKind::Fresnel;
    std::string title;                // what is plotted, for which parameters (the layout wraps it)
    std::string subtitle;             // how to read it: the radius, R0, the normalisation
    glm::vec2 min{0.0f}, max{1.0f};   // the rectangle of plot coordinates that is shown
    bool equalAspect = false;         // one unit spans as many pixels along x as along y (polar plots)
    std::vector<PlotPolyline> lines;  // in drawing order: grid first, curves last
    std::vector<PlotLabel> labels;
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

// What the plots take beside the scene: the lobe's incoming direction, and which side of the surface
// the Fresnel plot's light comes from.
struct PlotSettings {
    float incidenceDeg = 45.0f;   // angle between I and N, 0..kIncidenceDegRange.hi
    bool fromInside = false;      // false: from air into the material (eta1 = 1, eta2 = ior), as the
                                  // renderer's Fresnel term; true: eta1 = ior, eta2 = 1 (total internal reflection)
};

// The plot for a scene: the lobe at material.ke with the scene's reflection model, normalisation,
// Fresnel mode and ior; the Fresnel curves for the scene's ior, from the side settings.fromInside says.
Plot scenePlot(PlotKind kind, const Scene& scene, const Material& material, const PlotSettings& settings);

// ---- Layout: shared by the PNG rasteriser and the panel

// Measures a single line of text in pixels (width, height).
using MeasureText = std::function<glm::vec2(const std::string&)>;

struct PlotLegendEntry {
    std::size_t line = 0;             // index into Plot::lines
    glm::vec2 swatchFrom{0.0f}, swatchTo{0.0f};  // a short stroke in the line's style
    glm::vec2 textAt{0.0f};           // top-left
};

// Where everything goes in a width x height pixel rectangle (origin top-left, y down): title and
// subtitle on top, the legend under them (wrapping), the plot area below with room for axis labels.
struct PlotLayout {
    struct Line {
        std::string text;
        glm::vec2 at{0.0f};                     // top-left
        Rgba8 color;
    };
    std::vector<Line> header;                   // title and subtitle, wrapped at spaces to fit the width
    std::vector<PlotLegendEntry> legend;
    glm::vec2 areaMin{0.0f}, areaMax{0.0f};     // the pixels that plot.min..max map onto
    float lineHeight = 0.0f;
    glm::vec2 pixelsPerUnit{1.0f};              // y is flipped: larger plot y is higher up
    glm::vec2 plotOrigin{0.0f};                 // the pixel of plot point (0, 0)
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
