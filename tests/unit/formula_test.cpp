// The formula overlay's layout (core/figures/formula.hpp): which runs exist for each reflection model,
// normalisation and Fresnel mode, which term `show` isolates and which it dims, the values under the
// symbols, and where the overlay sits. A fixed-width font (half the size per character) stands in for
// the painters' fonts, so positions are known without a font file.
#include "core/figures/formula.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace shadelab;

namespace {

std::size_t characters(const std::string& s) {
    return std::size_t(std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

const TextMetrics kFixed{[](const std::string& s, float size) { return 0.5f * size * float(characters(s)); }, 0.8f};

FormulaLayout layout(const FormulaInput& in) { return layoutFormula(in, 20.0f, kFixed); }

// Every run's text in order (a script is a run of its own: k_a reads "ka").
std::string allText(const FormulaLayout& l) {
    std::string text;
    for (const FormulaRun& r : l.runs) text += r.text + "|";
    return text;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

FormulaInput input(ReflectionModel model, SpecularNormalization n = SpecularNormalization::None,
                   FresnelMode f = FresnelMode::None) {
    FormulaInput in;
    in.env.model = model;
    in.env.normalization = n;
    in.env.fresnel = f;
    return in;
}

const FormulaRun* runNamed(const FormulaLayout& l, const std::string& text, FormulaRun::Kind kind) {
    for (const FormulaRun& r : l.runs)
        if (r.text == text && r.kind == kind) return &r;
    return nullptr;
}

}  // namespace

TEST(Formula, MainLineIsTheLecturesSumWithScripts) {
    const FormulaLayout l = layout(input(ReflectionModel::BlinnPhong));
    const std::string text = allText(l);
    // L = k_a·A·C + Σ_l v·L_l·(k_d·C·max(0, N·I_l) + k_s·S·spec_l)
    EXPECT_TRUE(contains(text, "L = |k|a|·A·C| + Σ|l| v·L|l|·(|k|d|·C·max(0, N·I|l|)| + |k|s|·S·spec|l|)|")) << text;
    // Subscripts are smaller and lower than their base.
    const auto k = std::find_if(l.runs.begin(), l.runs.end(), [](const FormulaRun& r) { return r.text == "k"; });
    ASSERT_NE(k, l.runs.end());
    const FormulaRun& a = *(k + 1);
    EXPECT_EQ(a.text, "a");
    EXPECT_LT(a.size, k->size);
    EXPECT_GT(a.baseline, k->baseline);
    EXPECT_NEAR(a.x, k->x + 0.5f * k->size, 1e-4f);
}

TEST(Formula, SpecLineFollowsTheReflectionModel) {
    const std::string blinn = allText(layout(input(ReflectionModel::BlinnPhong)));
    EXPECT_TRUE(contains(blinn, "spec|l| = |max(0, H|l|·N)|k|e|")) << blinn;
    EXPECT_FALSE(contains(blinn, "R(I")) << blinn;
    const std::string phong = allText(layout(input(ReflectionModel::Phong)));
    EXPECT_TRUE(contains(phong, "spec|l| = |max(0, R(I|l|)·V)|k|e|")) << phong;
    EXPECT_FALSE(contains(phong, "H|l|·N")) << phong;
    // The exponent is a superscript: higher than the line.
    const FormulaLayout l = layout(input(ReflectionModel::Phong));
    const FormulaRun* lobe = runNamed(l, "max(0, R(I", FormulaRun::Kind::Symbol);
    ASSERT_NE(lobe, nullptr);
    const FormulaRun* ke = nullptr;
    for (const FormulaRun& r : l.runs)
        if (r.text == "k" && r.kind == FormulaRun::Kind::Coefficient && r.baseline < lobe->baseline) ke = &r;
    ASSERT_NE(ke, nullptr);
}

TEST(Formula, NormalisationAndFresnelAddTheirFactors) {
    const std::string plain = allText(layout(input(ReflectionModel::BlinnPhong)));
    EXPECT_FALSE(contains(plain, "/40")) << plain;
    EXPECT_FALSE(contains(plain, "F(V·H")) << plain;
    EXPECT_TRUE(contains(allText(layout(input(ReflectionModel::BlinnPhong, SpecularNormalization::Energy))), " + 8)/40"));
    EXPECT_TRUE(contains(allText(layout(input(ReflectionModel::Phong, SpecularNormalization::Energy))), " + 2)/34"));

    const std::string schlick =
        allText(layout(input(ReflectionModel::BlinnPhong, SpecularNormalization::None, FresnelMode::Schlick)));
    EXPECT_TRUE(contains(schlick, " · F(V·H|l|)")) << schlick;
    // R_0 = ((1 - 1.5) / (1 + 1.5))^2 = 0.04 at the default index.
    EXPECT_TRUE(contains(schlick, "F = R|0| + (1 − R|0|)(1 − V·H|l|)|5|")) << schlick;
    EXPECT_TRUE(contains(schlick, "= 0.040,   n|1| = 1 (air), n|2| = 1.50")) << schlick;
    const std::string exact = allText(layout(input(ReflectionModel::Phong, SpecularNormalization::Energy, FresnelMode::Exact)));
    EXPECT_TRUE(contains(exact, " + 2)/34 · F(V·H|l|)")) << exact;
    EXPECT_TRUE(contains(exact, "F = (R|∥| + R|⊥|)/2")) << exact;
    // The Fresnel line adds height.
    EXPECT_GT(layout(input(ReflectionModel::Phong, SpecularNormalization::None, FresnelMode::Exact)).height,
              layout(input(ReflectionModel::Phong)).height);
}

// "show" isolates one term: its box is tinted, its runs stay opaque, every other term's runs dim.
TEST(Formula, ShowIsolatesOneTermAndDimsTheOthers) {
    const struct {
        ShowTerm show;
        std::vector<FormulaTerm> isolated;
    } cases[] = {{ShowTerm::All, {}},
                 {ShowTerm::Ambient, {FormulaTerm::Ambient}},
                 {ShowTerm::Diffuse, {FormulaTerm::Diffuse}},
                 {ShowTerm::Specular, {FormulaTerm::Specular}},
                 {ShowTerm::Light, {FormulaTerm::Diffuse, FormulaTerm::Specular}},
                 {ShowTerm::Unlit, {}}};
    for (const auto& c : cases) {
        FormulaInput in = input(ReflectionModel::BlinnPhong);
        in.env.show.term = c.show;
        const FormulaLayout l = layout(in);
        const auto isolated = [&](FormulaTerm t) { return std::find(c.isolated.begin(), c.isolated.end(), t) != c.isolated.end(); };
        const std::string name = toString(in.env.show);
        for (const FormulaBox& b : l.boxes) EXPECT_EQ(b.isolated, isolated(b.term)) << name;
        for (const FormulaRun& r : l.runs) {
            const bool dim = r.term != FormulaTerm::None && c.show != ShowTerm::All && !isolated(r.term);
            EXPECT_EQ(r.color.a < 255, dim) << name << " " << r.text;
            if (r.term != FormulaTerm::None) {
                EXPECT_EQ(r.color.r, termColor(r.term).r) << name << " " << r.text;
            }
        }
    }
    FormulaInput in = input(ReflectionModel::BlinnPhong);
    in.env.show = TermView{ShowTerm::Light, 1};
    EXPECT_TRUE(contains(allText(layout(in)), "show: l = 1 only"));
    // The three terms have colours of their own.
    EXPECT_NE(termColor(FormulaTerm::Ambient).b, termColor(FormulaTerm::Diffuse).b);
    EXPECT_NE(termColor(FormulaTerm::Diffuse).r, termColor(FormulaTerm::Specular).r);
}

// k_a, k_d, k_s under their symbols on the main line, k_e under the exponent.
TEST(Formula, CoefficientValuesSitUnderTheirSymbols) {
    FormulaInput in = input(ReflectionModel::BlinnPhong);
    in.material.ka = 0.05f, in.material.kd = 0.7f, in.material.ks = 0.25f, in.material.ke = 100.0f;
    const FormulaLayout l = layout(in);
    const struct {
        const char* value;
        FormulaTerm term;
        const char* subscript;
    } cases[] = {{"0.050", FormulaTerm::Ambient, "a"}, {"0.70", FormulaTerm::Diffuse, "d"},
                 {"0.25", FormulaTerm::Specular, "s"}, {"100", FormulaTerm::Specular, "e"}};
    for (const auto& c : cases) {
        const FormulaRun* value = runNamed(l, c.value, FormulaRun::Kind::Value);
        const FormulaRun* symbol = runNamed(l, c.subscript, FormulaRun::Kind::Coefficient);
        ASSERT_NE(value, nullptr) << c.value << "\n" << allText(l);
        ASSERT_NE(symbol, nullptr) << c.subscript;
        EXPECT_EQ(value->term, c.term);
        EXPECT_GT(value->baseline, symbol->baseline) << c.value;  // below
        const float centre = value->x + 0.25f * value->size * float(characters(value->text));
        EXPECT_NEAR(centre, symbol->x, 0.5f * 20.0f) << c.value;  // under the k and its subscript
    }
}

// With a probed pixel, each term's RGB under its term (left to right, none overlapping); without, none.
TEST(Formula, ProbedValuesUnderEachTerm) {
    FormulaInput in = input(ReflectionModel::BlinnPhong);
    const auto rgbRuns = [](const FormulaLayout& l) {
        std::vector<FormulaRun> runs;
        for (const FormulaRun& r : l.runs)
            if (r.kind == FormulaRun::Kind::Value && r.text.find('(') != std::string::npos) runs.push_back(r);
        return runs;
    };
    EXPECT_TRUE(rgbRuns(layout(in)).empty());
    ShadingTerms t;
    t.ambient = {0.1f, 0.2f, 0.3f}, t.diffuse = {0.5f, 0.25f, 0.125f}, t.specular = {0.9f, 0.9f, 0.9f};
    t.total = {1.0f, 1.0f, 1.0f};
    in.probed = t;
    in.probedAt = "at pixel 3,4";
    const FormulaLayout l = layout(in);
    EXPECT_NE(runNamed(l, "at pixel 3,4", FormulaRun::Kind::Note), nullptr);
    const std::vector<FormulaRun> runs = rgbRuns(l);
    ASSERT_EQ(runs.size(), 4u);
    EXPECT_EQ(runs[0].text, "= (1.00 1.00 1.00)");
    EXPECT_EQ(runs[1].text, "(0.10 0.20 0.30)");
    EXPECT_EQ(runs[1].term, FormulaTerm::Ambient);
    EXPECT_EQ(runs[2].text, "(0.50 0.25 0.12)");
    EXPECT_EQ(runs[2].term, FormulaTerm::Diffuse);
    EXPECT_EQ(runs[3].text, "(0.90 0.90 0.90)");
    EXPECT_EQ(runs[3].term, FormulaTerm::Specular);
    for (std::size_t i = 1; i < runs.size(); ++i)
        EXPECT_LE(runs[i - 1].x + kFixed.width(runs[i - 1].text, runs[i - 1].size), runs[i].x) << i;
    EXPECT_GT(l.height, layout(input(ReflectionModel::BlinnPhong)).height);
}

TEST(Formula, EachModeSaysWhereItEvaluates) {
    EXPECT_EQ(evaluatedWhere(ShadingMode::Flat), "Flat: once per triangle, at its centroid");
    EXPECT_EQ(evaluatedWhere(ShadingMode::Gouraud), "Gouraud: at each vertex, colours interpolated");
    EXPECT_EQ(evaluatedWhere(ShadingMode::Phong), "Phong: at each pixel, normal interpolated");
}

// The overlay: the formula at the bottom of the view, centred, inside it; one note per pane above it.
TEST(Formula, OverlaySitsAtTheBottomWithANotePerPane) {
    const FormulaInput in = input(ReflectionModel::BlinnPhong);
    std::vector<FormulaPane> panes;
    for (int i = 0; i < 3; ++i) panes.push_back({float(i) * 400.0f, 0.0f, 400.0f, 700.0f, ShadingMode(i), false});
    const FormulaOverlay o = layoutFormulaOverlay(in, 1200.0f, 700.0f, panes, 16.0f, kFixed);
    EXPECT_GT(o.y, 350.0f);  // below the middle
    EXPECT_LE(o.y + o.formula.height, 700.0f);
    EXPECT_NEAR(o.x + 0.5f * o.formula.width, 600.0f, 1.0f);
    ASSERT_EQ(o.notes.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        const FormulaNote& n = o.notes[i];
        EXPECT_EQ(n.text, evaluatedWhere(ShadingMode(i)));
        EXPECT_LE(n.y + n.size + n.pad, o.y) << i;                     // above the formula
        EXPECT_GE(n.x - n.pad, panes[i].x) << i;                       // inside its pane
        EXPECT_LE(n.x + n.width + n.pad, panes[i].x + 400.0f + 1.0f) << i;
    }
    // Narrow panes (issue 31: at 2x the Gouraud pane's line was smaller than the others): one size for all.
    std::vector<FormulaPane> narrowPanes;
    for (int i = 0; i < 3; ++i) narrowPanes.push_back({float(i) * 250.0f, 0.0f, 250.0f, 700.0f, ShadingMode(i), false});
    const FormulaOverlay small = layoutFormulaOverlay(in, 750.0f, 700.0f, narrowPanes, 16.0f, kFixed);
    ASSERT_EQ(small.notes.size(), 3u);
    EXPECT_LT(small.notes[1].size, 1.1f * 16.0f);  // the longest line, Gouraud's, had to shrink ...
    for (const FormulaNote& n : small.notes) EXPECT_EQ(n.size, small.notes[1].size);  // ... and the others with it
    // A narrow view gets a smaller formula that fits.
    const FormulaOverlay narrow = layoutFormulaOverlay(in, 450.0f, 700.0f, {}, 16.0f, kFixed);
    EXPECT_LE(narrow.formula.width, 450.0f - 16.0f);
    EXPECT_LT(narrow.formula.height, o.formula.height);
}
