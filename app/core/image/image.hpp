#pragma once
// 8-bit RGBA images, PNG input/output (libpng; stb on Windows) and the image comparison used by the golden tests.
#include <cstdint>
#include <string>
#include <vector>

namespace shadelab {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // rows top to bottom, 4 bytes per pixel

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(std::size_t(w) * std::size_t(h) * 4, 0) {}
    const std::uint8_t* pixel(int x, int y) const { return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
    std::uint8_t* pixel(int x, int y) { return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
};

// Writes a PNG atomically (temporary + rename). zlib level 1 is ~4x faster than the default level 6
// for rendered frames at a modest size cost; golden images use 9 to keep the repository small.
void writePng(const std::string& path, const Image& image, int compressionLevel = 1);
// Reads any PNG as RGBA8. InputError naming the file if it is missing or not a PNG.
Image readPng(const std::string& path);

// Golden-image metric. Per pixel, the difference is the largest absolute difference of its R, G, B
// channels (0..255). A pixel "fails" when that exceeds `pixelThreshold`; the images match when the
// share of failing pixels is at most `maxFailingShare` and the mean difference at most `maxMean`.
struct CompareTolerance {
    int pixelThreshold = 8;
    double maxFailingShare = 0.001;
    double maxMean = 0.5;
};
struct CompareResult {
    bool sizeMatches = false;
    int maxDifference = 0;
    double meanDifference = 0.0;
    std::size_t failingPixels = 0;
    double failingShare = 0.0;
    bool matches(const CompareTolerance& t) const {
        return sizeMatches && failingShare <= t.maxFailingShare && meanDifference <= t.maxMean;
    }
};
CompareResult compareImages(const Image& actual, const Image& expected, int pixelThreshold);
// Visualises a comparison: grey copy of `expected`, failing pixels in red, smaller differences in
// yellow with brightness proportional to the difference.
Image differenceImage(const Image& actual, const Image& expected, int pixelThreshold);
std::string describe(const CompareResult& r, const CompareTolerance& t);

}  // namespace shadelab
