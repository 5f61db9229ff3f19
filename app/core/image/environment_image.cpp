#include "core/image/environment_image.hpp"

#include "core/base/error.hpp"
#include "core/image/image.hpp"

#include <stb/stb_image.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>

namespace shadelab {
namespace {

std::string lowerExtension(const std::string& path) {
    const std::size_t dot = path.find_last_of('.');
    const std::size_t slash = path.find_last_of("/\\");
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string e = path.substr(dot);
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e;
}

float decodeSrgb(std::uint8_t v) {
    const float c = float(v) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

void checkSize(const std::string& path, int w, int h) {
    if (w > kEnvironmentImageMaxSide || h > kEnvironmentImageMaxSide)
        throw InputError(path + ": environment image too large (at most " + std::to_string(kEnvironmentImageMaxSide) +
                         " pixels a side)");
    if (w < 2 || h < 1) throw InputError(path + ": environment image too small (at least 2 x 1 pixels)");
}

EnvironmentImage readHdr(const std::string& path) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) throw InputError(path + ": cannot open the environment image");
    int w = 0, h = 0, channels = 0;
    if (!stbi_is_hdr_from_file(file.get())) throw InputError(path + ": not a Radiance .hdr file");
    if (!stbi_info_from_file(file.get(), &w, &h, &channels))
        throw InputError(path + ": cannot read the .hdr file: " + stbi_failure_reason());
    checkSize(path, w, h);
    std::unique_ptr<float, void (*)(void*)> pixels(stbi_loadf_from_file(file.get(), &w, &h, &channels, 3),
                                                   &stbi_image_free);
    if (!pixels) throw InputError(path + ": cannot read the .hdr file: " + stbi_failure_reason());
    EnvironmentImage img{w, h, std::vector<float>(pixels.get(), pixels.get() + std::size_t(w) * std::size_t(h) * 3)};
    for (float& v : img.rgb)
        if (!std::isfinite(v) || v < 0.0f) v = 0.0f;
    return img;
}

EnvironmentImage readPngEnvironment(const std::string& path) {
    const Image png = readPng(path);
    checkSize(path, png.width, png.height);
    EnvironmentImage img{png.width, png.height,
                         std::vector<float>(std::size_t(png.width) * std::size_t(png.height) * 3)};
    for (std::size_t p = 0; p < std::size_t(png.width) * std::size_t(png.height); ++p)
        for (std::size_t c = 0; c < 3; ++c) img.rgb[3 * p + c] = decodeSrgb(png.rgba[4 * p + c]);
    return img;
}

}  // namespace

EnvironmentImage readEnvironmentImage(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".png") return readPngEnvironment(path);
    if (ext == ".hdr") return readHdr(path);
    throw InputError(path + ": an environment is room, sky, or a .png or .hdr file");
}

}  // namespace shadelab
