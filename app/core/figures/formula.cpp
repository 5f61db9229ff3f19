#include "core/figures/formula.hpp"

#include "core/shading/environment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadelab {
namespace {

// Scripts are 70% of their base's size, subscripts drop by 0.2 and superscripts rise by 0.38 of it.
constexpr float kScript = 0.7f, kSubDrop = 0.2f, kSupRise = 0.38f;
// The Fresnel line, which is long, relative to the main line.
constexpr float kFresnelSize = 0.8f;

constexpr Rgba8 kSymbolColor{240, 240, 240, 255};
constexpr Rgba8 kNoteColor{200, 200, 200, 255};
constexpr std::uint8_t kDimAlpha = 110;

struct Span {
    float x0 = 0, x1 = 0;
    float centre() const { return 0.5f * (x0 + x1); }
};

// Sets markup into runs: `_x` and `^x` (one character) or `_{...}` and `^{...}` (a group, nestable)
// are sub- and superscripts; everything else is text as it is.
class Typesetter {
public:
    Typesetter(std::vector<FormulaRun>& runs, const TextMetrics& metrics) : runs_(runs), metrics_(metrics) {}

    Span set(const std::string& markup, float x, float baseline, float size, Rgba8 color, FormulaTerm term,
             FormulaRun::Kind kind = FormulaRun::Kind::Symbol) {
        style_ = {color, term, kind};
        std::size_t i = 0;
        return Span{x, group(markup, i, false, x, baseline, size)};
    }

private:
    struct Style {
        Rgba8 color;
        FormulaTerm term = FormulaTerm::None;
        FormulaRun::Kind kind = FormulaRun::Kind::Symbol;
    };

    float emit(const std::string& text, float x, float baseline, float size) {
        if (text.empty()) return x;
        runs_.push_back(FormulaRun{text, x, baseline, size, style_.color, style_.term, style_.kind});
        return x + metrics_.width(text, size);
    }

    // One UTF-8 character starting at s[i].
    static std::string character(const std::string& s, std::size_t& i) {
        std::size_t end = i + 1;
        while (end < s.size() && (static_cast<unsigned char>(s[end]) & 0xC0) == 0x80) ++end;
        std::string c = s.substr(i, end - i);
        i = end;
        return c;
    }

    // Sets s from i up to the end (or the closing brace of a group); returns the x where it ends.
    float group(const std::string& s, std::size_t& i, bool inBraces, float x, float baseline, float size) {
        std::string text;
        while (i < s.size()) {
            const char c = s[i];
            if (inBraces && c == '}') {
                ++i;
                break;
            }
            if (c != '_' && c != '^') {
                text += character(s, i);
                continue;
            }
            x = emit(text, x, baseline, size);
            text.clear();
            ++i;
            const float scriptBaseline = c == '_' ? baseline + kSubDrop * size : baseline - kSupRise * size;
            if (i < s.size() && s[i] == '{') {
                ++i;
                x = group(s, i, true, x, scriptBaseline, size * kScript);
            } else if (i < s.size()) {
                x = emit(character(s, i), x, scriptBaseline, size * kScript);
            }
        }
        return emit(text, x, baseline, size);
    }

    std::vector<FormulaRun>& runs_;
    const TextMetrics& metrics_;
    Style style_;
};

Rgba8 dimmed(Rgba8 c) { return Rgba8{c.r, c.g, c.b, kDimAlpha}; }

// The lobe's factors after max(0, ...)^k_e: the energy normalisation's n(k_e)/n(32), written out
// (lighting.hpp: (k_e + 2)/34 for Phong, (k_e + 8)/40 for Blinn-Phong), and the Fresnel weight.
std::string lobeFactors(const FormulaInput& in) {
    std::string s;
    if (in.env.normalization == SpecularNormalization::Energy)
        s += anisotropicLobe(in.material, in.env)     ? " · √((k_t + 1)(k_b + 1))/33"
             : in.env.model == ReflectionModel::Phong ? " · (k_e + 2)/34"
                                                      : " · (k_e + 8)/40";
    if (in.env.fresnel != FresnelMode::None) s += " · F(V·H_l)";
    return s;
}

// The Fresnel line in the lecture's notation (Schlick's approximation, or the unpolarised average).
std::string fresnelLine(const FormulaInput& in) {
    const std::string media = "n_1 = 1 (air), n_2 = " + formulaNumber(in.env.ior);
    if (in.env.fresnel == FresnelMode::Schlick)
        return "F = R_0 + (1 − R_0)(1 − V·H_l)^5,   R_0 = ((n_1 − n_2)/(n_1 + n_2))^2 = " +
               formulaNumber(fresnelR0(1.0f, in.env.ior)) + ",   " + media;
    return "F = (R_∥ + R_⊥)/2  (exact Fresnel),   " + media;
}

// Anisotropic reflection's exponent (Ashikhmin and Shirley's), with the material's k_t and k_b.
std::string anisotropyLine(const FormulaInput& in) {
    return "k(H_l) = (k_t (H_l·T)^2 + k_b (H_l·B)^2) / (1 − (H_l·N)^2),   k_t = " +
           formulaNumber(in.material.anisotropy.x) + " along T,  k_b = " + formulaNumber(in.material.anisotropy.y) +
           " along B";
}

// Mirror and glass after the sum (core/shading/environment.hpp), with the material's k_r and k_t. No
// Greek: the viewer's formula font has only the characters the overlay needs (viewer/imgui_layer.cpp).
std::string mirrorGlassLine(const FormulaInput& in) {
    const bool f = in.env.fresnel != FresnelMode::None;
    return std::string("+ k_r") + (f ? " F" : "") + " env(R) + k_t" + (f ? " (1 − F)" : "") +
           " env(T),   R = 2(N·V)N − V,   T by Snell's law (ior " + formulaNumber(in.env.ior) +
           "),   k_r = " + formulaNumber(in.material.mirror) + ",  k_t = " + formulaNumber(in.material.transmission);
}

// E's own line: what a glTF material's emission is made of.
constexpr const char* kEmissiveLine =
    "E = emissiveFactor · emissiveTexture(uv) · emissiveStrength   (glTF: the light the surface gives off)";

// What the main line says after its bracket when `show` draws one light or the unlit colour.
std::string showNote(const TermView& show) {
    if (show.term == ShowTerm::Light) return "   show: l = " + std::to_string(show.light) + " only";
    if (show.term == ShowTerm::Unlit) return "   show: C alone (unlit)";
    return "";
}

// Lays out the formula's rows top to bottom; each row's baseline follows the one above.
class FormulaBuilder {
public:
    FormulaBuilder(const FormulaInput& in, float size, const TextMetrics& metrics)
        : in_(in),
          size_(size),
          metrics_(metrics),
          set_(layout_.runs, metrics),
          pad_(0.5f * size),
          valueSize_(in.valueSize) {
        layout_.corner = 0.3f * size;
    }

    FormulaLayout build() {
        float baseline = pad_ + metrics_.ascent * size_;
        mainLine(baseline);
        baseline = nextBaseline(baseline, size_, valueSize_ * size_);
        coefficientValues(baseline);
        if (in_.probed) {
            baseline = nextBaseline(baseline, valueSize_ * size_, valueSize_ * size_);
            probedValues(baseline);
        }
        baseline = nextBaseline(baseline, valueSize_ * size_, size_) + 0.15f * size_;
        specLine(baseline);
        baseline = nextBaseline(baseline, size_, valueSize_ * size_);
        keValue(baseline);
        float bottom = baseline + (1.0f - metrics_.ascent) * valueSize_ * size_;
        if (in_.emissive) {
            baseline = nextBaseline(baseline, valueSize_ * size_, kFresnelSize * size_) + 0.1f * size_;
            const Span s = set_.set(kEmissiveLine, pad_, baseline, kFresnelSize * size_, color(FormulaTerm::Emissive),
                                    FormulaTerm::Emissive);
            box(FormulaTerm::Emissive, s, baseline, kFresnelSize * size_);
            bottom = baseline + (1.0f - metrics_.ascent) * kFresnelSize * size_;
        }
        if (mirrorOrGlass(in_.material, in_.env.environment)) {
            baseline = nextBaseline(baseline, valueSize_ * size_, kFresnelSize * size_) + 0.1f * size_;
            const Span s = set_.set(mirrorGlassLine(in_), pad_, baseline, kFresnelSize * size_,
                                    color(FormulaTerm::Specular), FormulaTerm::Specular);
            box(FormulaTerm::Specular, s, baseline, kFresnelSize * size_);
            bottom = baseline + (1.0f - metrics_.ascent) * kFresnelSize * size_;
        }
        if (anisotropicLobe(in_.material, in_.env)) {
            baseline = nextBaseline(baseline, valueSize_ * size_, kFresnelSize * size_) + 0.1f * size_;
            const Span s = set_.set(anisotropyLine(in_), pad_, baseline, kFresnelSize * size_,
                                    color(FormulaTerm::Specular), FormulaTerm::Specular);
            box(FormulaTerm::Specular, s, baseline, kFresnelSize * size_);
            bottom = baseline + (1.0f - metrics_.ascent) * kFresnelSize * size_;
        }
        if (in_.env.fresnel != FresnelMode::None) {
            baseline = nextBaseline(baseline, valueSize_ * size_, kFresnelSize * size_) + 0.1f * size_;
            const Span s = set_.set(fresnelLine(in_), pad_, baseline, kFresnelSize * size_,
                                    color(FormulaTerm::Specular), FormulaTerm::Specular);
            box(FormulaTerm::Specular, s, baseline, kFresnelSize * size_);
            bottom = baseline + (1.0f - metrics_.ascent) * kFresnelSize * size_;
        }
        for (const FormulaRun& r : layout_.runs)
            layout_.width = std::max(layout_.width, r.x + metrics_.width(r.text, r.size));
        layout_.width += pad_;
        layout_.height = bottom + pad_;
        return layout_;
    }

private:
    float nextBaseline(float baseline, float above, float below) const {
        return baseline + (1.0f - metrics_.ascent) * above + metrics_.ascent * below + 0.05f * size_;
    }

    Rgba8 color(FormulaTerm term) const {
        const Rgba8 c = term == FormulaTerm::None ? kSymbolColor : termColor(term);
        return termDimmed(in_.env.show, term) ? dimmed(c) : c;
    }

    Span piece(const std::string& markup, FormulaTerm term, float baseline,
               FormulaRun::Kind kind = FormulaRun::Kind::Symbol) {
        const Span s = set_.set(markup, x_, baseline, size_, color(term), term, kind);
        x_ = s.x1;
        if (term != FormulaTerm::None) termSpan(term, s);
        return s;
    }

    void termSpan(FormulaTerm term, const Span& s) {
        Span& t = spans_[int(term)];
        t = t.x1 > t.x0 ? Span{std::min(t.x0, s.x0), std::max(t.x1, s.x1)} : s;
    }

    void box(FormulaTerm term, const Span& s, float baseline, float size) {
        const float margin = 0.12f * size;
        layout_.boxes.push_back(FormulaBox{term, s.x0 - margin, baseline - metrics_.ascent * size - margin,
                                           s.x1 + margin, baseline + (1.0f - metrics_.ascent) * size + margin,
                                           termIsolated(in_.env.show, term)});
    }

    void mainLine(float baseline) {
        x_ = pad_;
        lSpan_ = piece("L = ", FormulaTerm::None, baseline);
        if (in_.emissive) {
            piece("E", FormulaTerm::Emissive, baseline);
            piece(" + ", FormulaTerm::None, baseline);
        }
        kSpans_[0] = piece("k_a", FormulaTerm::Ambient, baseline, FormulaRun::Kind::Coefficient);
        piece("·A·C", FormulaTerm::Ambient, baseline);
        piece(" + Σ_l v·L_l·(", FormulaTerm::None, baseline);
        kSpans_[1] = piece("k_d", FormulaTerm::Diffuse, baseline, FormulaRun::Kind::Coefficient);
        piece("·C·max(0, N·I_l)", FormulaTerm::Diffuse, baseline);
        piece(" + ", FormulaTerm::None, baseline);
        kSpans_[2] = piece("k_s", FormulaTerm::Specular, baseline, FormulaRun::Kind::Coefficient);
        piece("·S·spec_l", FormulaTerm::Specular, baseline);
        piece(")", FormulaTerm::None, baseline);
        const std::string note = showNote(in_.env.show);
        if (!note.empty())
            set_.set(note, x_, baseline, valueSize_ * size_, kNoteColor, FormulaTerm::None, FormulaRun::Kind::Note);
        for (FormulaTerm t : {FormulaTerm::Ambient, FormulaTerm::Diffuse, FormulaTerm::Specular})
            box(t, spans_[int(t)], baseline, size_);
        if (in_.emissive) box(FormulaTerm::Emissive, spans_[int(FormulaTerm::Emissive)], baseline, size_);
    }

    // A value centred under `under`, pushed right of the previous one on its row so none overlap.
    void valueUnder(const Span& under, const std::string& text, FormulaTerm term, float baseline, float& rowEnd) {
        const float size = valueSize_ * size_;
        const float w = metrics_.width(text, size);
        const float x = std::max(under.centre() - 0.5f * w, rowEnd);
        set_.set(text, x, baseline, size, color(term), term, FormulaRun::Kind::Value);
        rowEnd = x + w + 0.6f * size;
    }

    void coefficientValues(float baseline) {
        float rowEnd = 0.0f;
        const Material& m = in_.material;
        valueUnder(kSpans_[0], formulaNumber(m.ka), FormulaTerm::Ambient, baseline, rowEnd);
        valueUnder(kSpans_[1], formulaNumber(m.kd), FormulaTerm::Diffuse, baseline, rowEnd);
        valueUnder(kSpans_[2], formulaNumber(m.ks), FormulaTerm::Specular, baseline, rowEnd);
    }

    // The probed pixel: L (what is drawn, clamped) under L, each term's RGB under its span.
    void probedValues(float baseline) {
        const ShadingTerms& t = *in_.probed;
        float rowEnd = 0.0f;
        const float size = valueSize_ * size_;
        set_.set("= " + formulaRgb(t.total), lSpan_.x0, baseline, size, kSymbolColor, FormulaTerm::None,
                 FormulaRun::Kind::Value);
        rowEnd = lSpan_.x0 + metrics_.width("= " + formulaRgb(t.total), size) + 0.6f * size;
        if (in_.emissive)
            valueUnder(spans_[int(FormulaTerm::Emissive)], formulaRgb(t.emissive), FormulaTerm::Emissive, baseline,
                       rowEnd);
        valueUnder(spans_[int(FormulaTerm::Ambient)], formulaRgb(t.ambient), FormulaTerm::Ambient, baseline, rowEnd);
        valueUnder(spans_[int(FormulaTerm::Diffuse)], formulaRgb(t.diffuse), FormulaTerm::Diffuse, baseline, rowEnd);
        valueUnder(spans_[int(FormulaTerm::Specular)], formulaRgb(t.specular), FormulaTerm::Specular, baseline, rowEnd);
        if (!in_.probedAt.empty())
            set_.set(in_.probedAt, rowEnd + 0.6f * size, baseline, size, kNoteColor, FormulaTerm::None,
                     FormulaRun::Kind::Note);
    }

    void specLine(float baseline) {
        x_ = pad_;
        const float start = x_;
        piece("spec_l = ", FormulaTerm::Specular, baseline);
        piece(in_.env.model == ReflectionModel::Phong ? "max(0, R(I_l)·V)" : "max(0, H_l·N)", FormulaTerm::Specular,
              baseline);
        keSpan_ = piece(anisotropicLobe(in_.material, in_.env) ? "^{k(H_l)}" : "^{k_e}", FormulaTerm::Specular,
                        baseline, FormulaRun::Kind::Coefficient);
        piece(lobeFactors(in_), FormulaTerm::Specular, baseline);
        box(FormulaTerm::Specular, Span{start, x_}, baseline, size_);
    }

    void keValue(float baseline) {
        float rowEnd = 0.0f;
        // Anisotropic: the exponent varies with H; its line below gives k_t and k_b.
        if (!anisotropicLobe(in_.material, in_.env))
            valueUnder(keSpan_, formulaNumber(in_.material.ke), FormulaTerm::Specular, baseline, rowEnd);
    }

    const FormulaInput& in_;
    float size_;
    const TextMetrics& metrics_;
    FormulaLayout layout_;
    Typesetter set_;
    float pad_;
    float x_ = 0;
    Span spans_[5];  // by FormulaTerm
    Span kSpans_[3], keSpan_, lSpan_;
    const float valueSize_;  // FormulaInput::valueSize
};

}  // namespace

Rgba8 termColor(FormulaTerm term) {
    switch (term) {
    case FormulaTerm::Ambient: return Rgba8{110, 175, 255, 255};
    case FormulaTerm::Diffuse: return Rgba8{115, 225, 105, 255};
    case FormulaTerm::Specular: return Rgba8{255, 205, 60, 255};
    case FormulaTerm::Emissive: return Rgba8{255, 130, 200, 255};
    case FormulaTerm::None: break;
    }
    return kSymbolColor;
}

bool termIsolated(const TermView& show, FormulaTerm term) {
    switch (show.term) {
    case ShowTerm::Ambient: return term == FormulaTerm::Ambient;
    case ShowTerm::Diffuse: return term == FormulaTerm::Diffuse;
    case ShowTerm::Specular: return term == FormulaTerm::Specular;
    case ShowTerm::Light: return term == FormulaTerm::Diffuse || term == FormulaTerm::Specular;
    case ShowTerm::Emissive: return term == FormulaTerm::Emissive;
    case ShowTerm::All:
    case ShowTerm::Unlit: break;
    }
    return false;
}

bool termDimmed(const TermView& show, FormulaTerm term) {
    if (term == FormulaTerm::None || show.term == ShowTerm::All) return false;
    return !termIsolated(show, term);
}

FormulaInput formulaInput(const Scene& scene, const Material& material) {
    FormulaInput in;
    in.env = lightingEnvironment(scene);
    in.material = material;
    in.emissive = scene.emissiveModel || material.emissive != glm::vec3(0.0f);
    return in;
}

FormulaLayout layoutFormula(const FormulaInput& in, float size, const TextMetrics& metrics) {
    return FormulaBuilder(in, size, metrics).build();
}

FormulaLayout layoutFormulaToFit(const FormulaInput& in, float size, float maxWidth, const TextMetrics& metrics) {
    FormulaLayout l = layoutFormula(in, size, metrics);
    for (float s = size * 0.9f; l.width > maxWidth && s >= size * 0.5f; s *= 0.9f) l = layoutFormula(in, s, metrics);
    return l;
}

FormulaOverlay layoutFormulaOverlay(const FormulaInput& in, float viewWidth, float viewHeight,
                                    const std::vector<FormulaPane>& panes, float fontSize, const TextMetrics& metrics) {
    FormulaOverlay o;
    const float margin = 0.5f * fontSize;
    o.formula = layoutFormulaToFit(in, kFormulaSize * fontSize, viewWidth - 2.0f * margin, metrics);
    o.x = std::round(std::max(0.5f * (viewWidth - o.formula.width), 0.0f));
    o.y = std::round(viewHeight - margin - o.formula.height);
    // One size for every pane's line: where a pane is narrower than its line, all get smaller (down to
    // 60%; a line still too wide is cut), so no pane's note reads smaller than its neighbours'.
    float noteSize = 1.1f * fontSize;
    for (const FormulaPane& p : panes) {
        const float width = metrics.width(evaluatedWhere(p.mode, p.difference), 1.1f * fontSize);
        if (width > p.width * 0.95f)
            noteSize = std::min(noteSize, 1.1f * fontSize * std::max(p.width * 0.95f / std::max(width, 1.0f), 0.6f));
    }
    for (const FormulaPane& p : panes) {
        FormulaNote n;
        n.text = evaluatedWhere(p.mode, p.difference);
        n.size = noteSize;
        n.width = metrics.width(n.text, n.size);
        n.pad = 0.3f * n.size;
        n.x = std::round(p.x + std::max(0.5f * (p.width - n.width), n.pad));
        n.y = std::round(std::min(o.y, p.y + p.height) - margin - n.size - n.pad);
        o.notes.push_back(std::move(n));
    }
    return o;
}

std::string evaluatedWhere(ShadingMode mode, bool differencePane) {
    if (differencePane) return "the difference of the two panes' pixels, no formula";
    switch (mode) {
    case ShadingMode::Flat: return "Flat: once per triangle, at its centroid";
    case ShadingMode::Gouraud: return "Gouraud: at each vertex, colours interpolated";
    case ShadingMode::Phong: break;
    }
    return "Phong: at each pixel, normal interpolated";
}

std::string formulaNumber(float value) {
    char text[32];
    if (std::fabs(value) >= 1.0f && std::fabs(value - std::round(value)) < 1e-4f)
        std::snprintf(text, sizeof text, "%.0f", double(value));
    else if (std::fabs(value) < 0.1f && value != 0.0f) std::snprintf(text, sizeof text, "%.3f", double(value));
    else std::snprintf(text, sizeof text, "%.2f", double(value));
    return text;
}

std::string formulaRgb(const glm::vec3& rgb) {
    char text[64];
    std::snprintf(text, sizeof text, "(%.2f %.2f %.2f)", double(rgb.r), double(rgb.g), double(rgb.b));
    return text;
}

}  // namespace shadelab
