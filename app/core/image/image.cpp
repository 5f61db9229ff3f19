#include "core/image/image.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "platform/platform.hpp"

#if SHADELAB_PNG_STB
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#else
#include <png.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace shadelab {

namespace {
using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

File openPng(const std::string& path) {
    File file(platform::openFile(path, "rb"), &std::fclose);
    if (!file) throw InputError(path + ": cannot read PNG: " + std::strerror(errno));
    return file;
}
}  // namespace

#if SHADELAB_PNG_STB
// stb_image_write and stb_image (Debian's libstb-dev headers): the Windows build's PNG codec, as Debian
// has no MinGW build of libpng. Same pixels in and out; the files are somewhat larger.

void writePng(const std::string& path, const Image& img, int level) {
    writeFileAtomic(path, [&](std::FILE* f) {
        stbi_write_png_compression_level = level;
        bool written = true;
        struct Sink {
            std::FILE* file;
            bool* ok;
        } sink{f, &written};
        const auto put = [](void* context, void* data, int size) {
            const Sink& to = *static_cast<Sink*>(context);
            *to.ok = *to.ok && std::fwrite(data, 1, std::size_t(size), to.file) == std::size_t(size);
        };
        const int encoded =
            stbi_write_png_to_func(put, &sink, img.width, img.height, 4, img.rgba.data(), img.width * 4);
        if (!encoded) throw InputError(path + ": cannot write: the PNG encoder failed");
        return written;
    });
}

std::string encodePng(const Image& img, int level) {
    stbi_write_png_compression_level = level;
    std::string bytes;
    const auto put = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
    };
    if (!stbi_write_png_to_func(put, &bytes, img.width, img.height, 4, img.rgba.data(), img.width * 4))
        throw std::runtime_error("the PNG encoder failed");
    return bytes;
}

Image readPng(const std::string& path) {
    const File file = openPng(path);
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char signature[8] = {};
    if (std::fread(signature, 1, 8, file.get()) != 8 || std::memcmp(signature, kSignature, 8) != 0 ||
        std::fseek(file.get(), 0, SEEK_SET) != 0)
        throw InputError(path + ": cannot read PNG: not a PNG file");
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_file(file.get(), &w, &h, &channels))
        throw InputError(path + ": cannot read PNG: " + stbi_failure_reason());
    if (w > 16384 || h > 16384) throw InputError(path + ": PNG too large");
    std::unique_ptr<unsigned char, void (*)(void*)> pixels(stbi_load_from_file(file.get(), &w, &h, &channels, 4),
                                                           &stbi_image_free);
    if (!pixels) throw InputError(path + ": cannot read PNG: " + stbi_failure_reason());
    Image img(w, h);
    std::memcpy(img.rgba.data(), pixels.get(), img.rgba.size());
    return img;
}

#else
// libpng.

namespace {
// libpng reports through these instead of printing: a refusal stays one line (a full disk was
// "libpng error: Write Error" on stderr before shadelab's own message).
struct PngErrors {
    std::string message;
};
[[noreturn]] void pngError(png_structp png, png_const_charp message) {
    static_cast<PngErrors*>(png_get_error_ptr(png))->message = message;
    png_longjmp(png, 1);
}
void pngWarning(png_structp, png_const_charp) {}
}  // namespace

// The settings of every PNG shadelab writes: RGBA8, no interlacing, the Sub filter at low levels.
void setUpPng(png_structp png, png_infop info, const Image& img, int level) {
    png_set_compression_level(png, level);
    // Rendered frames are smooth gradients: the Sub filter alone compresses them nearly as well as
    // adaptive filtering at a fraction of the cost.
    png_set_filter(png, PNG_FILTER_TYPE_BASE, level <= 3 ? PNG_FILTER_SUB : PNG_ALL_FILTERS);
    png_set_IHDR(png, info, png_uint_32(img.width), png_uint_32(img.height), 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < img.height; ++y) png_write_row(png, img.pixel(0, y));
    png_write_end(png, nullptr);
}

void writePng(const std::string& path, const Image& img, int level) {
    writeFileAtomic(path, [&](std::FILE* f) {
        PngErrors errors;
        png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, pngError, pngWarning);
        if (!png) return false;
        png_infop info = png_create_info_struct(png);
        if (!info || setjmp(png_jmpbuf(png))) {
            png_destroy_write_struct(&png, &info);
            // A stream error (ENOSPC, EIO) says more than libpng's "Write Error".
            throw InputError(
                path + ": cannot write: " +
                (std::ferror(f) && errno ? std::string(std::strerror(errno)) : "libpng: " + errors.message));
        }
        png_init_io(png, f);
        setUpPng(png, info, img, level);
        png_destroy_write_struct(&png, &info);
        return true;
    });
}

std::string encodePng(const Image& img, int level) {
    PngErrors errors;
    std::string bytes;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, pngError, pngWarning);
    if (!png) throw std::runtime_error("libpng: cannot start the encoder");
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw std::runtime_error("libpng: " + errors.message);
    }
    const auto put = [](png_structp p, png_bytep data, png_size_t size) {
        static_cast<std::string*>(png_get_io_ptr(p))->append(reinterpret_cast<const char*>(data), size);
    };
    png_set_write_fn(png, &bytes, put, [](png_structp) {});
    setUpPng(png, info, img, level);
    png_destroy_write_struct(&png, &info);
    return bytes;
}

Image readPng(const std::string& path) {
    const File file = openPng(path);
    png_image desc{};
    desc.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_stdio(&desc, file.get()))
        throw InputError(path + ": cannot read PNG: " + desc.message);
    desc.format = PNG_FORMAT_RGBA;
    if (desc.width > 16384 || desc.height > 16384) {
        png_image_free(&desc);
        throw InputError(path + ": PNG too large");
    }
    Image img(int(desc.width), int(desc.height));
    if (!png_image_finish_read(&desc, nullptr, img.rgba.data(), 0, nullptr))
        throw InputError(path + ": cannot read PNG: " + desc.message);
    return img;
}

#endif

namespace {
// A pixel's difference: the largest of its channels' (R, G, B and A), 0..255.
int pixelDifference(const std::uint8_t* a, const std::uint8_t* b) {
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
    return d;
}
}  // namespace

CompareResult compareImages(const Image& a, const Image& e, int pixelThreshold) {
    CompareResult r;
    r.pixelThreshold = pixelThreshold;
    r.sizeMatches = a.width == e.width && a.height == e.height;
    if (!r.sizeMatches) return r;
    double channelSum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        const std::uint8_t *pa = &a.rgba[i], *pe = &e.rgba[i];
        for (int c = 0; c < 4; ++c) channelSum += std::abs(int(pa[c]) - int(pe[c]));
        const int d = pixelDifference(pa, pe);
        r.maxDiff = std::max(r.maxDiff, d);
        if (d > pixelThreshold) ++r.differingPixels;
    }
    const double n = double(a.width) * double(a.height);
    r.meanDiff = n > 0 ? channelSum / (4.0 * n) : 0.0;
    return r;
}

bool ImageTolerance::matches(const CompareResult& r) const {
    if (r.pixelThreshold != pixelThreshold)
        throw std::logic_error("ImageTolerance::matches: the result counts pixels over another threshold");
    return r.sizeMatches && r.maxDiff <= maxDiff && r.meanDiff <= meanDiff &&
           (!maxDiffPixels || r.differingPixels <= *maxDiffPixels);
}

ImageTolerance toleranceWithShare(int width, int height, int pixelThreshold, double share, double meanDiff) {
    ImageTolerance t;
    t.maxDiff = 255;
    t.meanDiff = meanDiff;
    t.pixelThreshold = pixelThreshold;
    t.maxDiffPixels = std::uint64_t(share * double(width) * double(height));
    return t;
}

std::string describe(const CompareResult& r, const ImageTolerance& t) {
    if (!r.sizeMatches) return "image sizes differ";
    char mean[32];
    std::snprintf(mean, sizeof mean, "%.3g", r.meanDiff);
    std::ostringstream s;
    s << "max " << r.maxDiff << "/255 (limit " << t.maxDiff << "), mean " << mean << " (limit " << t.meanDiff << ")";
    if (t.maxDiffPixels) {
        s << ", " << r.differingPixels << (r.differingPixels == 1 ? " pixel differs" : " pixels differ");
        if (r.pixelThreshold > 0) s << " by more than " << r.pixelThreshold << "/255";
        s << " (limit " << *t.maxDiffPixels << ")";
    }
    return s.str();
}

Image differenceImage(const Image& a, const Image& e, int threshold) {
    Image d(e.width, e.height);
    for (int y = 0; y < e.height; ++y)
        for (int x = 0; x < e.width; ++x) {
            const std::uint8_t* pe = e.pixel(x, y);
            std::uint8_t* out = d.pixel(x, y);
            const int diff = (x < a.width && y < a.height) ? pixelDifference(a.pixel(x, y), pe) : 255;
            const auto grey = std::uint8_t((int(pe[0]) + int(pe[1]) + int(pe[2])) / 12);
            if (diff > threshold) {
                out[0] = 255;
                out[1] = 0;
                out[2] = 0;
            } else if (diff > 0) {
                const auto v = std::uint8_t(std::min(255, 64 + diff * 191 / std::max(threshold, 1)));
                out[0] = v;
                out[1] = v;
                out[2] = 0;
            } else {
                out[0] = out[1] = out[2] = grey;
            }
            out[3] = 255;
        }
    return d;
}

Image amplifiedDifference(const Image& a, const Image& b, float factor) {
    if (a.width != b.width || a.height != b.height) throw std::invalid_argument("amplifiedDifference: sizes differ");
    Image d(a.width, a.height);
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        // As difference.frag: clamp(|a - b| x factor, 0, 1), stored to 8 bits rounded to nearest.
        for (std::size_t c = 0; c < 3; ++c)
            d.rgba[i + c] = std::uint8_t(
                std::min(255L, std::lround(float(std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]))) * factor)));
        d.rgba[i + 3] = 255;
    }
    return d;
}

}  // namespace shadelab
