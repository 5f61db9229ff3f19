#pragma once
// What the plots' builders share (plot.cpp: the lobe and Fresnel plots; brdf_plot.cpp: the 3-D lobe
// and the BRDF slices): their colours, number labels, the subtitles' modifiers, and the polyline and
// label values they emit.
// Internal to core/figures.
#include "core/figures/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace shadelab::plot_parts {

// Curve colours (see kPlotBackground): Okabe-Ito orange, sky blue, vermillion, bluish green and yellow,
// lightened where the original is too dark on the dark background.
constexpr Rgba8 kOrange{240, 170, 40, 255};
constexpr Rgba8 kSkyBlue{86, 180, 233, 255};
constexpr Rgba8 kVermillion{240, 100, 60, 255};
constexpr Rgba8 kGreen{40, 200, 150, 255};
constexpr Rgba8 kYellow{240, 228, 66, 255};
constexpr Rgba8 kPurple{204, 121, 167, 255};

inline std::string format(const char* fmt, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, fmt, value);
    return buffer;
}

// "0.25", "2", "1.5e+03": short labels for ring and tick values.
inline std::string shortNumber(float v) { return format("%g", double(v)); }

// The smallest step of 1, 2, 2.5 or 5 times a power of ten with `count` steps reaching `peak`.
inline float niceStep(float peak, int count) {
    const float raw = std::max(peak, 1e-12f) / float(count);
    const float decade = std::pow(10.0f, std::floor(std::log10(raw)));
    for (float m : {1.0f, 2.0f, 2.5f, 5.0f, 10.0f})
        if (m * decade * float(count) >= peak * (1.0f - 1e-6f)) return m * decade;
    return 10.0f * decade;
}

// What else shapes the specular term: normalisation and Fresnel, as the subtitles say them
// (", energy-normalised, times F(V.H) exact for ior 1.50"; empty for neither).
inline std::string specularModifiers(const LightingEnvironment& env) {
    std::string s;
    if (env.normalization == SpecularNormalization::Energy) s += ", energy-normalised";
    if (env.fresnel != FresnelMode::None)
        s += std::string(", times F(V.H) ") + toString(env.fresnel) + " for ior " + format("%.2f", double(env.ior));
    return s;
}

inline PlotPolyline line(std::string name, std::vector<glm::vec2> points, Rgba8 color, float width = 1.0f) {
    PlotPolyline l;
    l.name = std::move(name);
    l.points = std::move(points);
    l.color = color;
    l.width = width;
    return l;
}

inline PlotLabel label(glm::vec2 at, std::string text, glm::vec2 align, glm::vec2 offset, Rgba8 color = kPlotText) {
    return PlotLabel{at, std::move(text), align, offset, color};
}

}  // namespace shadelab::plot_parts
