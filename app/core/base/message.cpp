#include "core/base/message.hpp"

#include <cstdint>
#include <cstdio>

namespace shadelab {
namespace {

// Length of the valid UTF-8 sequence at text[i] that is not a C1 control, or 0.
std::size_t utf8Length(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b = byte(i);
    std::size_t n = 0;
    std::uint32_t cp = 0;
    if (b >= 0xC2 && b <= 0xDF) {
        n = 2;
        cp = b & 0x1Fu;
    } else if (b >= 0xE0 && b <= 0xEF) {
        n = 3;
        cp = b & 0x0Fu;
    } else if (b >= 0xF0 && b <= 0xF4) {
        n = 4;
        cp = b & 0x07u;
    } else {
        return 0;
    }
    if (i + n > text.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0u) != 0x80u) return 0;
        cp = cp << 6 | (byte(i + k) & 0x3Fu);
    }
    const bool overlong = (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
    if (overlong || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF) || (cp >= 0x80 && cp <= 0x9F)) return 0;
    return n;
}

}  // namespace

std::string escapeControls(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto b = static_cast<unsigned char>(text[i]);
        if (b >= 0x20 && b < 0x7F) {
            out += char(b);
            ++i;
        } else if (const std::size_t n = b >= 0x80 ? utf8Length(text, i) : 0) {
            out.append(text.substr(i, n));
            i += n;
        } else {
            if (b == '\n') out += "\\n";
            else if (b == '\t') out += "\\t";
            else if (b == '\r') out += "\\r";
            else {
                char hex[8];
                std::snprintf(hex, sizeof hex, "\\x%02x", unsigned(b));
                out += hex;
            }
            ++i;
        }
    }
    return out;
}

namespace {
// `text` cut to at most `limit` bytes without splitting a UTF-8 sequence.
std::string_view cutAt(std::string_view text, std::size_t limit) {
    if (text.size() <= limit) return text;
    std::size_t n = limit;
    while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0u) == 0x80u) --n;
    return text.substr(0, n);
}
}  // namespace

std::string quoteInput(std::string_view text, std::size_t limit) {
    if (text.size() <= limit) return escapeControls(text);
    return escapeControls(cutAt(text, limit)) + "...(" + std::to_string(text.size()) + " bytes)";
}

std::string oneLine(std::string_view message, std::size_t limit) {
    std::string line = escapeControls(message);
    if (line.size() <= limit) return line;
    const std::size_t tail = limit / 5, head = limit - tail - 40;
    std::size_t tailStart = line.size() - tail;
    while (tailStart < line.size() && (static_cast<unsigned char>(line[tailStart]) & 0xC0u) == 0x80u) ++tailStart;
    const std::string_view kept = cutAt(line, head);
    return std::string(kept) + " [... " + std::to_string(tailStart - kept.size()) + " bytes ...] " +
           line.substr(tailStart);
}

std::string joinedLines(std::string log) {
    while (!log.empty() && log.back() == '\n') log.pop_back();
    for (std::size_t at = 0; (at = log.find('\n', at)) != std::string::npos;)
        log.replace(at, 1, at > 0 && log[at - 1] == ':' ? " " : "; ");
    return log;
}

}  // namespace shadelab
