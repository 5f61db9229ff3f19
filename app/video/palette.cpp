#include "video/palette.hpp"

#include <algorithm>
#include <unordered_map>

namespace shadelab {
namespace {

using Key = std::uint32_t;  // 0x00RRGGBB

Key keyOf(const std::uint8_t* p) { return Key(p[0]) << 16 | Key(p[1]) << 8 | Key(p[2]); }
int channel(Key k, int c) { return int(k >> (16 - 8 * c)) & 0xFF; }

// A box of the median cut: colours[begin, end) of the distinct colours.
struct Box {
    std::size_t begin, end;
    int widest = 0;  // the channel with the largest extent
    int extent = 0;  // that extent (0: one colour, or all equal)
};

Box measured(const std::vector<Key>& colours, std::size_t begin, std::size_t end) {
    Box box{begin, end};
    for (int c = 0; c < 3; ++c) {
        int lo = 255, hi = 0;
        for (std::size_t i = begin; i < end; ++i) {
            lo = std::min(lo, channel(colours[i], c));
            hi = std::max(hi, channel(colours[i], c));
        }
        if (hi - lo > box.extent) {
            box.extent = hi - lo;
            box.widest = c;
        }
    }
    return box;
}

// Splits the widest box at its median until there are 256 (or no box has two different colours).
// `colours` is reordered so that each box is a range of it.
std::vector<Box> medianCut(std::vector<Key>& colours) {
    std::vector<Box> boxes{measured(colours, 0, colours.size())};
    while (boxes.size() < 256) {
        const auto widest = std::max_element(boxes.begin(), boxes.end(),
                                             [](const Box& a, const Box& b) { return a.extent < b.extent; });
        if (widest->extent == 0) break;
        const Box box = *widest;
        const int c = box.widest;
        const std::size_t middle = box.begin + (box.end - box.begin) / 2;
        std::nth_element(colours.begin() + long(box.begin), colours.begin() + long(middle),
                         colours.begin() + long(box.end), [c](Key a, Key b) { return channel(a, c) < channel(b, c); });
        *widest = measured(colours, box.begin, middle);
        boxes.push_back(measured(colours, middle, box.end));
    }
    return boxes;
}

std::size_t nearest(const std::vector<std::array<std::uint8_t, 3>>& palette, int r, int g, int b) {
    std::size_t best = 0;
    int bestDistance = 1 << 30;
    for (std::size_t i = 0; i < palette.size(); ++i) {
        const int dr = palette[i][0] - r, dg = palette[i][1] - g, db = palette[i][2] - b;
        const int d = dr * dr + dg * dg + db * db;
        if (d < bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    return best;
}

// Floyd-Steinberg: each pixel's error (in 1/16ths) goes to its right and lower neighbours.
void ditherInto(const Image& frame, PalettedImage& out) {
    const int w = frame.width;
    std::vector<int> error(std::size_t(w + 2) * 3 * 2, 0);  // this row and the next, one pixel of margin each side
    std::unordered_map<Key, std::uint8_t> cache;
    for (int y = 0; y < frame.height; ++y) {
        int* row = &error[std::size_t(y % 2) * std::size_t(w + 2) * 3];
        int* below = &error[std::size_t((y + 1) % 2) * std::size_t(w + 2) * 3];
        std::fill(below, below + (w + 2) * 3, 0);
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* p = frame.pixel(x, y);
            int want[3];
            for (int c = 0; c < 3; ++c) want[c] = std::clamp(p[c] + row[(x + 1) * 3 + c] / 16, 0, 255);
            const Key key = Key(want[0]) << 16 | Key(want[1]) << 8 | Key(want[2]);
            auto found = cache.find(key);
            if (found == cache.end())
                found = cache.emplace(key, std::uint8_t(nearest(out.palette, want[0], want[1], want[2]))).first;
            out.indices[std::size_t(y) * std::size_t(w) + std::size_t(x)] = found->second;
            for (int c = 0; c < 3; ++c) {
                const int e = want[c] - out.palette[found->second][std::size_t(c)];
                row[(x + 2) * 3 + c] += e * 7;
                below[x * 3 + c] += e * 3;
                below[(x + 1) * 3 + c] += e * 5;
                below[(x + 2) * 3 + c] += e;
            }
        }
    }
}

}  // namespace

PalettedImage paletteFrame(const Image& frame, bool dither) {
    PalettedImage out;
    out.width = frame.width;
    out.height = frame.height;
    const std::size_t pixels = std::size_t(frame.width) * std::size_t(frame.height);
    if (pixels == 0) return out;
    std::vector<Key> colours(pixels);
    for (std::size_t i = 0; i < pixels; ++i) colours[i] = keyOf(&frame.rgba[i * 4]);
    std::sort(colours.begin(), colours.end());
    colours.erase(std::unique(colours.begin(), colours.end()), colours.end());
    // Each distinct colour's palette entry (sorted by colour below, for a binary search per pixel).
    std::vector<std::pair<Key, std::uint8_t>> entryOf;
    for (const Box& box : medianCut(colours)) {
        long sum[3] = {0, 0, 0};
        for (std::size_t i = box.begin; i < box.end; ++i)
            for (int c = 0; c < 3; ++c) sum[c] += channel(colours[i], c);
        const long n = long(box.end - box.begin);
        const std::array<std::uint8_t, 3> mean{std::uint8_t((sum[0] + n / 2) / n), std::uint8_t((sum[1] + n / 2) / n),
                                               std::uint8_t((sum[2] + n / 2) / n)};
        // Two boxes can have the same mean: one entry for both. Each entry is a colour of its own, which
        // libavcodec's GIF encoder needs (FFmpeg 5.1 maps a repeated colour's index to entry 0).
        auto entry = std::find(out.palette.begin(), out.palette.end(), mean);
        if (entry == out.palette.end()) entry = out.palette.insert(out.palette.end(), mean);
        for (std::size_t i = box.begin; i < box.end; ++i)
            entryOf.emplace_back(colours[i], std::uint8_t(entry - out.palette.begin()));
    }
    out.indices.resize(pixels);
    if (dither) {
        ditherInto(frame, out);
        return out;
    }
    std::sort(entryOf.begin(), entryOf.end());
    for (std::size_t i = 0; i < pixels; ++i) {
        const Key key = keyOf(&frame.rgba[i * 4]);
        out.indices[i] = std::lower_bound(entryOf.begin(), entryOf.end(), std::make_pair(key, std::uint8_t(0)))->second;
    }
    return out;
}

}  // namespace shadelab
