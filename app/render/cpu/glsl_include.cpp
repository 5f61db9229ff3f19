#include "render/cpu/glsl_include.hpp"

#include <cctype>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace shadelab {
namespace {

void expandInto(const std::string& name, const std::function<std::string(const std::string&)>& load, ExpandedGlsl& out,
                int depth) {
    if (depth > 16) throw std::runtime_error(name + ": includes nested deeper than 16");
    for (const auto& f : out.files)
        if (f == name) return;  // already included in this program
    const int id = int(out.files.size());
    out.files.push_back(name);
    std::istringstream in(load(name));
    std::string line;
    int lineNo = 0;
    const auto lineDirective = [id](int n) {
        return "#line " + std::to_string(id * kGlslLinesPerFile + n) + " " + std::to_string(id) + "\n";
    };
    out.text += lineDirective(1);
    while (std::getline(in, line)) {
        ++lineNo;
        const size_t first = line.find_first_not_of(" \t");
        if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
            const size_t open = line.find('"', first), close = line.find('"', open + 1);
            if (open == std::string::npos || close == std::string::npos)
                throw std::runtime_error(name + ":" + std::to_string(lineNo) + ": malformed #include");
            expandInto(line.substr(open + 1, close - open - 1), load, out, depth + 1);
            out.text += lineDirective(lineNo + 1);
        } else if (first != std::string::npos && line.compare(first, 8, "#version") == 0) {
            throw std::runtime_error(name + ":" + std::to_string(lineNo) +
                                     ": #version is added by the include step; remove it");
        } else {
            out.text += line + "\n";
        }
    }
}

}  // namespace

ExpandedGlsl expandGlsl(const std::string& name, const std::function<std::string(const std::string&)>& load,
                        const std::vector<std::string>& defines) {
    ExpandedGlsl out;
    out.text = kGlslPrologue;
    for (const std::string& d : defines) out.text += "#define " + d + "\n";
    expandInto(name, load, out, 0);
    return out;
}

std::string locateGlslLog(const std::string& log, const std::vector<std::string>& files) {
    // A log line starts (after blanks and an optional "ERROR: " or "WARNING: ") with
    // "SOURCE:LINE", e.g. Mesa's "0:12(5): error: ...": replace SOURCE by its file name.
    std::istringstream in(log);
    std::string line, result;
    while (std::getline(in, line)) {
        size_t p = line.find_first_not_of(" \t");
        for (const char* prefix : {"ERROR: ", "WARNING: "})
            if (p != std::string::npos && line.compare(p, std::strlen(prefix), prefix) == 0) p += std::strlen(prefix);
        size_t digits = p;
        while (digits < line.size() && std::isdigit(static_cast<unsigned char>(line[digits]))) ++digits;
        if (p != std::string::npos && digits > p && digits + 1 < line.size() && line[digits] == ':' &&
            std::isdigit(static_cast<unsigned char>(line[digits + 1]))) {
            size_t id = std::stoul(line.substr(p, digits - p));
            size_t end = digits + 1;
            while (end < line.size() && std::isdigit(static_cast<unsigned char>(line[end]))) ++end;
            std::string number = line.substr(digits + 1, end - digits - 1);
            if (number.size() < 10) {  // the file in the line number wins (see kGlslLinesPerFile)
                const unsigned long n = std::stoul(number);
                if (n >= unsigned(kGlslLinesPerFile)) {
                    id = n / kGlslLinesPerFile;
                    number = std::to_string(n % kGlslLinesPerFile);
                }
            }
            if (id < files.size()) line = line.substr(0, p) + files[id] + ":" + number + line.substr(end);
        }
        result += line + "\n";
    }
    return result;
}

}  // namespace shadelab
