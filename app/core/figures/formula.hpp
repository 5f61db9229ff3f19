#pragma once
// The lecture's formula as the viewer (key E) and `--formula` draw it over the view: a GL-free layout
// of coloured text runs with their positions, typeset from a small TeX-like markup (k_a, ^{k_e}), which
// two painters draw: ImGui's draw lists in the viewer (viewer/formula_view.cpp) and the TrueType
// text renderer into a headless image (core/figures/formula_image.hpp). So both show the same thing.
//
//   L = k_a·A·C + Σ_l v·L_l·(k_d·C·max(0, N·I_l) + k_s·S·spec_l)
//   spec_l = max(0, H_l·N)^k_e  (Blinn-Phong) or max(0, R(I_l)·V)^k_e (Phong)  [· (k_e + 8)/40] [· F(V·H_l)]
//   F = ... (Schlick or the exact average, with Fresnel on)
// with k_a, k_d, k_s, k_e's values under their symbols and, with a probed pixel, each term's value.
#include "core/image/text.hpp"
#include "core/scene/scene.hpp"
#include "core/shading/lighting.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

// Which addend of the formula a run belongs to (None: L, =, +, Σ, brackets).
enum class FormulaTerm { None, Ambient, Diffuse, Specular, Emissive };

// Each term's colour (on a dark backing): ambient blue, diffuse green, specular gold. The shader view
// marks the lines that compute a term in the same colour.
Rgba8 termColor(FormulaTerm term);

// Whether `show` isolates this term (then it is highlighted and the others dimmed). With "all" none
// is; "light:N" isolates the diffuse and specular of one light; "unlit" none (every term dims).
bool termIsolated(const TermView& show, FormulaTerm term);
// Whether `show` dims this term: some other addend (or the unlit colour) is what is drawn.
bool termDimmed(const TermView& show, FormulaTerm term);

// One piece of text in one size and colour. Positions are pixels from the layout's top-left corner.
struct FormulaRun {
    std::string text;  // UTF-8
    float x = 0, baseline = 0;
    float size = 0;  // line height (ascent - descent of the font), as ImGui sizes its fonts
    Rgba8 color;
    FormulaTerm term = FormulaTerm::None;
    enum class Kind { Symbol, Coefficient, Value, Note } kind = Kind::Symbol;  // value: a k or a probed term
};

// A term's span on the formula's lines; the isolated term's box gets a tinted backing.
struct FormulaBox {
    FormulaTerm term = FormulaTerm::None;
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool isolated = false;
};

struct FormulaLayout {
    std::vector<FormulaRun> runs;
    std::vector<FormulaBox> boxes;
    float width = 0, height = 0;  // the backing, padding included
    float corner = 0;             // the backing's corner radius
};

inline constexpr float kFormulaValueSize = 0.62f;

// What the formula shows: the scene's reflection model and factors, the material whose k are shown,
// and optionally the terms at a probed pixel (ProbeResult -> probedTerms, core/probe/probe.hpp).
struct FormulaInput {
    LightingEnvironment env;  // its model, normalization, fresnel, ior and show
    Material material;
    bool emissive = false;  // the scene draws a glTF material that gives off light: L = E + ...
    std::optional<ShadingTerms> probed;
    std::string probedAt;  // where: "at pixel 1050,330", at the end of the probed values' row
    // The k values, probed terms and notes under the symbols, relative to the main line: the PNG's
    // kFormulaValueSize; the viewer shows them as large as the symbols (1) for the back of a hall.
    float valueSize = kFormulaValueSize;
};
FormulaInput formulaInput(const Scene& scene, const Material& material);

// How the painter's font measures text: the advance of a UTF-8 string at line height `size`, and the
// ascent as a fraction of the line height.
struct TextMetrics {
    std::function<float(const std::string& utf8, float size)> width;
    float ascent = 0.8f;
};

// The formula for line height `size` (the main line; scripts and values smaller).
FormulaLayout layoutFormula(const FormulaInput& in, float size, const TextMetrics& metrics);

// The layout at the largest size up to `size` (in 10% steps, down to half) whose width fits `maxWidth`.
FormulaLayout layoutFormulaToFit(const FormulaInput& in, float size, float maxWidth, const TextMetrics& metrics);

// The whole overlay over a view: the formula centred at the bottom, and above it, at each pane's
// bottom, one line that says where that pane's mode evaluates the formula (evaluatedWhere). Units are
// the painter's (ImGui units in the viewer, pixels in an image), from the view's top-left corner.
struct FormulaPane {
    float x = 0, y = 0, width = 0, height = 0;
    ShadingMode mode = ShadingMode::Phong;
    bool difference = false;  // the diff layout's |A - B| pane
};
struct FormulaNote {
    std::string text;
    float x = 0, y = 0, size = 0;  // the text's top-left and line height
    float pad = 0;                 // its backing reaches this far around the text
    float width = 0;               // the text's advance
};
struct FormulaOverlay {
    FormulaLayout formula;
    float x = 0, y = 0;  // the formula's top-left
    std::vector<FormulaNote> notes;
};
// `fontSize`: the UI's text size (16 px x content scale x UI scale in the viewer); the formula's main
// line is 1.5 times that, smaller where the view is too narrow for it.
FormulaOverlay layoutFormulaOverlay(const FormulaInput& in, float viewWidth, float viewHeight,
                                    const std::vector<FormulaPane>& panes, float fontSize, const TextMetrics& metrics);
inline constexpr float kFormulaSize = 1.5f;                // the main line, in the UI's text sizes
inline constexpr std::uint8_t kFormulaBackingAlpha = 170;  // the translucent black under the formula and notes
inline constexpr std::uint8_t kIsolatedBoxAlpha = 70;      // the isolated term's tint

// Where a shading mode evaluates the formula, as each pane says it under the formula:
// "Flat: once per triangle, at its centroid", "Gouraud: at each vertex, colours interpolated",
// "Phong: at each pixel, normal interpolated"; the diff layout's difference pane says what it shows.
std::string evaluatedWhere(ShadingMode mode, bool differencePane = false);

// "0.70", "32", "(0.09, 0.03, 0.02)": numbers as the formula prints them.
std::string formulaNumber(float value);
std::string formulaRgb(const glm::vec3& rgb);

}  // namespace shadelab
