#pragma once
// 8-bit RGBA images, PNG input/output (libpng; stb on Windows) and the image comparison of the golden
// tests and --reference (run/reference.hpp).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // rows top to bottom, 4 bytes per pixel

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(std::size_t(w) * std::size_t(h) * 4, 0) {}
    const std::uint8_t* pixel(int x, int y) const {
        return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
    }
    std::uint8_t* pixel(int x, int y) { return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
};

// Writes a PNG atomically (temporary + rename). zlib level 1 is ~4x faster than the default level 6
// for rendered frames at a modest size cost; golden images use 9 to keep the repository small.
void writePng(const std::string& path, const Image& image, int compressionLevel = 1);
// Reads any PNG as RGBA8. InputError naming the file if it is missing or not a PNG.
Image readPng(const std::string& path);
// The PNG file's bytes, in memory (the --test report's images, inline as data: URIs). Throws
// std::runtime_error when the encoder fails.
std::string encodePng(const Image& image, int compressionLevel = 1);

// The image comparison, one metric for the golden tests, --reference, --test and the Python module: per
// channel, as magnum's DebugTools::CompareImage. Over every channel (R, G, B and A) of every pixel, the
// largest difference and the mean (/255); and the pixels where some channel differs by more than
// `pixelThreshold` (0: at all, as Playwright's maxDiffPixels counts them).
struct CompareResult {
    bool sizeMatches = false;
    int maxDiff = 0;
    double meanDiff = 0.0;
    int pixelThreshold = 0;  // what differingPixels counts
    std::size_t differingPixels = 0;
};
CompareResult compareImages(const Image& actual, const Image& expected, int pixelThreshold = 0);

// The thresholds on a CompareResult: the images match when they are of one size, no channel of any
// pixel differs by more than maxDiff, the mean over every channel of every pixel is at most meanDiff and
// at most maxDiffPixels pixels differ by more than pixelThreshold. The defaults are --reference's
// (run/reference.hpp, --max-diff and --mean-diff; the golden tests' are toleranceWithShare's).
//
// The defaults, measured with llvmpipe (Mesa 22.3, Debian 12) on the default scene, the default in the
// compare layout, lecture presets 06 (k_e 32), 14 (two objects) and 03 (layout diff, k_e 100) and the
// Suzanne glTF model, each at 1280x720, 320x240 and 160x120 (18 cases; max /255, mean):
//   llvmpipe against llvmpipe (EGL against OSMesa)   max 0-2 (2: layout diff), mean 0 - 2.3e-4 (Suzanne, 160x120)
//   k_e + 1 (32 -> 33, 100 -> 101)                  max 2,    mean 0.0084 - 0.064
//   k_e + 0.1 (the slider's displayed precision)    max 1-2,  mean 0.0008 - 0.0057 (about half fail)
//   the light moved 0.05 (a pixel of its drag)       max 2-46, mean 0.019 - 0.73
//   another shading mode (phong -> gouraud; diff's A) max 48-255, mean 0.13 - 9.9
// A one-step k_e change moves no channel more than the two backends do, so the mean is what tells
// them apart: 0.002 is 8x the largest llvmpipe mean; it catches k_e + 1 on every lecture preset up to
// k_e 64, not always from k_e ~100 up (measured: docs/ci.md, "What the defaults catch";
// 0.0001 catches them up to 256, but textured models differ more between the backends). The max
// of 4 lets a 1/255 flicker through layout diff's x4 pane, twice the largest measured, and still fails
// every mode change; OSMesa against EGL differs by 1/255 at a handful of pixels (cli_test.cpp).
struct ImageTolerance {
    int maxDiff = 4;
    double meanDiff = 0.002;
    // At most this many pixels may differ by more than pixelThreshold (--max-diff-pixels, a scene's
    // "test": "max_diff_pixels", both with pixelThreshold 0); none: no such limit.
    std::optional<std::uint64_t> maxDiffPixels;
    int pixelThreshold = 0;
    CompareResult compare(const Image& actual, const Image& expected) const {
        return compareImages(actual, expected, pixelThreshold);
    }
    // `r` must count its pixels with this pixelThreshold (compare() does): std::logic_error otherwise.
    bool matches(const CompareResult& r) const;
};
// The image tests' tolerance (golden images, a model's variant against the original, a window against
// a headless render): at most `share` of the width x height pixels may differ by more than
// `pixelThreshold`, by any amount (llvmpipe's vector width follows the CPU, AVX2 or AVX-512, which may
// flip a few silhouette pixels), and the mean over the channels at most `meanDiff`. The defaults are
// for two renders made by different paths (a variant, a window): 0.1% over 8/255, and a mean of
// 0.125/255, so each pixel's largest difference is at most 0.5/255 on the mean.
ImageTolerance toleranceWithShare(int width, int height, int pixelThreshold = 8, double share = 0.001,
                                  double meanDiff = 0.125);
// "max 3/255 (limit 4), mean 0.000123 (limit 0.002)", then ", 2 pixels differ (limit 5)" where
// maxDiffPixels is set ("differ by more than T/255" for a pixelThreshold T > 0); "image sizes differ"
// when they do. The mean to three significant digits (a single pixel off by 1/255 in a 1280x720
// frame is 2.71e-07, not 0).
std::string describe(const CompareResult& r, const ImageTolerance& t);
// Visualises a comparison: grey copy of `expected`, pixels that differ by more than `pixelThreshold`
// in red, smaller differences in yellow with brightness proportional to the difference.
Image differenceImage(const Image& actual, const Image& expected, int pixelThreshold);

// The difference pane's look (layout diff, shaders/difference.frag) on the CPU: per channel
// min(255, round(|a - b| x factor)), alpha 255. Both images of one size (else std::invalid_argument).
Image amplifiedDifference(const Image& a, const Image& b, float factor);

}  // namespace shadelab
