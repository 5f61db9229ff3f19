#pragma once
// Every numeric range of shadelab's inputs, defined once: the scene reader (scene_reader.cpp), the
// command line (options/option_table.cpp: its messages and --help print these), the sweep (sweep.cpp)
// and the viewer's panel all read them from here. GL-free, header-only.
#include <cmath>
#include <string>

namespace shadelab {

// A closed range lo..hi; `text()` is how messages and --help print it ("1..10").
template <typename T>
struct Range {
    T lo, hi;
    constexpr bool contains(T v) const { return v >= lo && v <= hi; }
};

// The scene.
inline constexpr Range<int> kLightCountRange{0, 16};    // also SL_MAX_LIGHTS in shaders/shared_defs.glsl
inline constexpr Range<int> kImageSideRange{1, 16384};  // pixels per side, refused before anything is allocated
// Procedural meshes' tessellation: scene files, --mesh and the sweep's "tessellation".
inline constexpr Range<int> kUvSphereSlicesRange{3, 4096};
inline constexpr Range<int> kUvSphereStacksRange{2, 2048};
inline constexpr Range<int> kIcoSphereSubdivisionsRange{0, 8};
inline constexpr Range<int> kTorusSegmentsRange{3, 4096};  // major and minor
inline constexpr Range<int> kPlaneSubdivisionsRange{1, 1024};
inline constexpr Range<float> kCoefficientRange{0.0f, 1000.0f};  // k_a, k_d, k_s
inline constexpr Range<float> kExponentRange{1.0f, 10000.0f};    // k_e: the lecture's slider goes 1..1000
inline constexpr Range<int> kAreaSamplesPerSideRange{1, 16};     // an area light has at most 16 x 16 samples
inline constexpr Range<float> kSpotConeDegRange{0.0f, 90.0f};    // a spot light's cone half-angles (glTF: pi / 2)
inline constexpr Range<int> kShadowMapSizeRange{64, 4096};       // shadow-map sides, pixels
inline constexpr Range<int> kPcfRadiusRange{0, 2};               // percentage-closer filtering: (2r+1)^2 lookups
inline constexpr Range<float> kColorRange{0.0f, 1.0f};  // each channel of C, S, A and the background (linear RGB)
// Relative index of refraction eta2 / eta1; below 1 the light arrives from the denser side ("from
// inside" the glass: total internal reflection past the critical angle).
inline constexpr Range<float> kIorRange{0.2f, 10.0f};
inline constexpr Range<float> kUnitRange{0.0f, 1.0f};           // mirror and transmission weights k_r, k_t
inline constexpr Range<float> kDiffFactorRange{1.0f, 1000.0f};  // layout "diff": |A - B| is multiplied by this
inline constexpr Range<float> kFovYDegRange{1.0f, 179.0f};      // the camera's vertical field of view
// Places, directions and sizes in world units, and the lights' values: the scene reader, --light and
// the panel. double, as the reader compares: 1e-4 has no exact float.
// Positions, directions, normals, the camera; an object's translation, rotation (degrees) and scale.
inline constexpr Range<double> kCoordinateRange{-1e6, 1e6};
inline constexpr Range<double> kSizeRange{1e-4, 1e6};        // radii, cube and plane sizes, area lights' sides
inline constexpr Range<double> kIntensityRange{0.0, 1e9};    // a light's intensity
inline constexpr Range<double> kLightRangeRange{1e-4, 1e9};  // a light's "range": 1/r^2 reaches zero there
inline constexpr Range<double> kSpotOuterConeDegRange{0.01, kSpotConeDegRange.hi};  // the inner cone: kSpotConeDegRange
inline constexpr Range<double> kShadowBiasRange{0.0, 100.0};  // normal bias (texels) and depth bias (slope)
// The lobe plot's angle between I and N: at 90 the light grazes the surface and spec is 0.
inline constexpr Range<float> kIncidenceDegRange{0.0f, 89.0f};

// Runs and the viewer.
inline constexpr Range<int> kBenchmarkFramesRange{1, 1000000};
inline constexpr Range<int> kViewerFramesRange{1, 100000000};
inline constexpr Range<int> kProgressiveStrideRange{1, 16};  // area-light samples spread over S*S frames
inline constexpr Range<float> kUiScaleRange{0.75f, 4.0f};    // on top of the monitor's content scale
// --reference's thresholds, in /255 (the defaults, and what they were measured against: core/image/image.hpp).
inline constexpr Range<int> kMaxDiffRange{0, 255};           // --max-diff: any channel of any pixel
inline constexpr Range<float> kMeanDiffRange{0.0f, 255.0f};  // --mean-diff: over every channel of every pixel
// --max-diff-pixels, "test": "max_diff_pixels": pixels that may differ (16384 x 16384 is the largest image).
inline constexpr Range<int> kMaxDiffPixelsRange{0, 268435456};
inline constexpr int kMaxTestMasks = 64;  // "test": "masks": rectangles per scene

// The light count's bound under the name the renderer and shaders/shared_defs.glsl (SL_MAX_LIGHTS) use.
inline constexpr int kMaxLights = kLightCountRange.hi;

// "1", "0.75", "1e+06": a number as messages print it (ostream's default format).
std::string formatNumber(double v);
// A bound as ranges print it: whole numbers in full ("1000000", not "1e+06"), others as formatNumber.
inline std::string boundText(double v) {
    return v == std::floor(v) && std::fabs(v) < 1e15 ? std::to_string(static_cast<long long>(v)) : formatNumber(v);
}
// "between 1 and 10": the wording of the range messages.
template <typename T>
std::string betweenText(const Range<T>& r) {
    return "between " + boundText(double(r.lo)) + " and " + boundText(double(r.hi));
}
// "1..16": the range as --help and the README print it.
template <typename T>
std::string rangeText(const Range<T>& r) {
    return boundText(double(r.lo)) + ".." + boundText(double(r.hi));
}

}  // namespace shadelab
