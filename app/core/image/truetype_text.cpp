#include "core/image/truetype_text.hpp"

#include <stb/stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>

namespace shadelab {
namespace {

constexpr const char* kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// The code points of a UTF-8 string; a malformed byte becomes U+FFFD.
std::vector<int> codePoints(const std::string& s) {
    std::vector<int> out;
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        const int length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
        if (length == 0 || i + std::size_t(length) > s.size()) {
            out.push_back(0xFFFD);
            ++i;
            continue;
        }
        int cp = length == 1 ? c : c & (0xFF >> (length + 1));
        bool ok = true;
        for (int k = 1; k < length; ++k) {
            const auto d = static_cast<unsigned char>(s[i + std::size_t(k)]);
            ok = ok && (d & 0xC0) == 0x80;
            cp = (cp << 6) | (d & 0x3F);
        }
        out.push_back(ok ? cp : 0xFFFD);
        i += ok ? std::size_t(length) : 1;
    }
    return out;
}

}  // namespace

struct TrueTypeFont::Impl {
    std::vector<unsigned char> data;
    stbtt_fontinfo info{};
    int ascent = 0, descent = 0, lineGap = 0;  // font units
};

TrueTypeFont::TrueTypeFont(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TrueTypeFont::~TrueTypeFont() = default;

const TrueTypeFont* TrueTypeFont::dejaVuSans() {
    static const std::unique_ptr<TrueTypeFont> font = []() -> std::unique_ptr<TrueTypeFont> {
        auto impl = std::make_unique<Impl>();
        std::ifstream in(kDejaVuSans, std::ios::binary);
        impl->data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if (impl->data.empty() ||
            !stbtt_InitFont(&impl->info, impl->data.data(), stbtt_GetFontOffsetForIndex(impl->data.data(), 0)))
            return nullptr;
        stbtt_GetFontVMetrics(&impl->info, &impl->ascent, &impl->descent, &impl->lineGap);
        return std::unique_ptr<TrueTypeFont>(new TrueTypeFont(std::move(impl)));
    }();
    return font.get();
}

float TrueTypeFont::ascent(float pixels) const {
    return float(impl_->ascent) * stbtt_ScaleForMappingEmToPixels(&impl_->info, pixels);
}

float TrueTypeFont::height(float pixels) const {
    return float(impl_->ascent - impl_->descent) * stbtt_ScaleForMappingEmToPixels(&impl_->info, pixels);
}

float TrueTypeFont::width(const std::string& utf8, float pixels) const {
    const float scale = stbtt_ScaleForMappingEmToPixels(&impl_->info, pixels);
    const std::vector<int> cps = codePoints(utf8);
    float x = 0.0f;
    for (std::size_t i = 0; i < cps.size(); ++i) {
        int advance = 0, bearing = 0;
        stbtt_GetCodepointHMetrics(&impl_->info, cps[i], &advance, &bearing);
        x += float(advance) * scale;
        if (i + 1 < cps.size()) x += float(stbtt_GetCodepointKernAdvance(&impl_->info, cps[i], cps[i + 1])) * scale;
    }
    return x;
}

void TrueTypeFont::draw(Image& image, float x, float y, const std::string& utf8, float pixels, Rgba8 color) const {
    const float scale = stbtt_ScaleForMappingEmToPixels(&impl_->info, pixels);
    const float baseline = y + ascent(pixels);
    const std::vector<int> cps = codePoints(utf8);
    float pen = x;
    for (std::size_t i = 0; i < cps.size(); ++i) {
        // Each glyph at its sub-pixel position, so letters keep their spacing at every size.
        const float shiftX = pen - std::floor(pen), shiftY = baseline - std::floor(baseline);
        int w = 0, h = 0, ox = 0, oy = 0;
        unsigned char* coverage =
            stbtt_GetCodepointBitmapSubpixel(&impl_->info, scale, scale, shiftX, shiftY, cps[i], &w, &h, &ox, &oy);
        const int x0 = int(std::floor(pen)) + ox, y0 = int(std::floor(baseline)) + oy;
        for (int gy = 0; gy < h; ++gy)
            for (int gx = 0; gx < w; ++gx) {
                const int px = x0 + gx, py = y0 + gy;
                if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
                const float a = float(coverage[gy * w + gx]) / 255.0f * float(color.a) / 255.0f;
                if (a <= 0.0f) continue;
                std::uint8_t* p = image.pixel(px, py);
                p[0] = std::uint8_t(std::lround(float(p[0]) + (float(color.r) - float(p[0])) * a));
                p[1] = std::uint8_t(std::lround(float(p[1]) + (float(color.g) - float(p[1])) * a));
                p[2] = std::uint8_t(std::lround(float(p[2]) + (float(color.b) - float(p[2])) * a));
            }
        stbtt_FreeBitmap(coverage, nullptr);
        int advance = 0, bearing = 0;
        stbtt_GetCodepointHMetrics(&impl_->info, cps[i], &advance, &bearing);
        pen += float(advance) * scale;
        if (i + 1 < cps.size()) pen += float(stbtt_GetCodepointKernAdvance(&impl_->info, cps[i], cps[i + 1])) * scale;
    }
}

}  // namespace shadelab
