#pragma once
// Environment images for mirrors and glass ("environment": FILE): an equirectangular picture of every
// direction around the scene, read into linear RGB floats. PNG (sRGB-encoded 8-bit, decoded with the
// sRGB curve) or Radiance .hdr (linear radiance, read by Debian's stb_image).
#include <string>
#include <vector>

namespace shadelab {

// Linear RGB, rows from the zenith (top) to the nadir, longitude across; see
// core/shading/environment.hpp for how a direction finds its texels.
struct EnvironmentImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // width * height * 3, rows top to bottom
};

// The largest side read (a 2:1 image of 8192 x 4096 floats is 384 MiB): refused beyond it.
inline constexpr int kEnvironmentImageMaxSide = 8192;

// Reads FILE.png or FILE.hdr (by its extension, case-insensitive). InputError naming the file when it
// is missing, of another kind, undecodable, larger than kEnvironmentImageMaxSide a side, or smaller
// than 2 x 1.
EnvironmentImage readEnvironmentImage(const std::string& path);

}  // namespace shadelab
