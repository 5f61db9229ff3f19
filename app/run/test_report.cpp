#include "run/test_report.hpp"

#include "core/base/message.hpp"
#include "core/scene/scene_limits.hpp"
#include "run/reference.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

namespace shadelab {
namespace {

namespace fs = std::filesystem;

const char* outcomeWord(CaseOutcome o) {
    return o == CaseOutcome::Match ? "matches" : o == CaseOutcome::Differs ? "differs" : "error";
}

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", s);
    return text;
}

// "a, b, c" of the cases `which` picks, at most `most` names then "and N more".
template <typename Which>
std::string namesOf(const TestRun& run, Which which, std::size_t most = 8) {
    std::string names;
    std::size_t n = 0;
    for (const TestCase& c : run.cases) {
        if (!which(c)) continue;
        if (n < most) names += (n ? ", " : "") + c.name;
        ++n;
    }
    if (n > most) names += " and " + std::to_string(n - most) + " more";
    return names;
}

// The message of a case that does not match, for the line, the JUnit attribute and the page.
std::string caseMessage(const TestCase& c) { return c.outcome == CaseOutcome::Match ? "" : c.message; }

}  // namespace

std::string shownPath(const fs::path& path) {
    std::error_code ec;
    const fs::path here = fs::current_path(ec);
    const fs::path absolute = fs::absolute(path, ec).lexically_normal();
    if (ec) return path.string();
    const fs::path relative = absolute.lexically_relative(here);
    if (relative.empty() || *relative.begin() == "..") return path.lexically_normal().generic_string();
    return relative.generic_string();
}

std::size_t countOf(const TestRun& run, CaseOutcome outcome) {
    return std::size_t(std::count_if(run.cases.begin(), run.cases.end(),
                                     [outcome](const TestCase& c) { return c.outcome == outcome; }));
}

namespace {

// The cases that failed and were not rewritten by --update, of `outcome`.
std::size_t countStill(const TestRun& run, CaseOutcome outcome) {
    return std::size_t(std::count_if(run.cases.begin(), run.cases.end(),
                                     [outcome](const TestCase& c) { return c.outcome == outcome && !c.updated; }));
}

}  // namespace

std::string caseLine(const TestRun& run, const TestCase& c) {
    return oneLine(
        "shadelab: --test " + run.dir + ": " + c.name + ": " + outcomeWord(c.outcome) + ": " + caseMessage(c), 2000);
}

std::string summaryLine(const TestRun& run) {
    const std::size_t differs = countStill(run, CaseOutcome::Differs), errors = countStill(run, CaseOutcome::Error);
    const std::size_t written =
        std::size_t(std::count_if(run.cases.begin(), run.cases.end(), [](const TestCase& c) { return c.updated; }));
    const auto still = [](CaseOutcome o) { return [o](const TestCase& c) { return c.outcome == o && !c.updated; }; };
    std::string line = "shadelab: --test " + run.dir + (run.shard.empty() ? "" : " (shard " + run.shard + ")") + ": " +
                       std::to_string(run.cases.size()) + " scene" + (run.cases.size() == 1 ? "" : "s") + ", " +
                       std::to_string(countOf(run, CaseOutcome::Match)) + " match";
    if (written)
        line += ", " + std::to_string(written) + " written (" +
                namesOf(run, [](const TestCase& c) { return c.updated; }) + ")";
    if (differs)
        line += ", " + std::to_string(differs) + " differ" + (differs == 1 ? "s" : "") + " (" +
                namesOf(run, still(CaseOutcome::Differs)) + ")";
    if (errors)
        line += ", " + std::to_string(errors) + " error" + (errors == 1 ? "" : "s") + " (" +
                namesOf(run, still(CaseOutcome::Error)) + ")";
    // A broken shader fails every case that uses it: its located error once, here, not once per case.
    std::set<std::string> shaderErrors;
    for (const TestCase& c : run.cases)
        if (c.shaderError && shaderErrors.insert(c.message).second) line += "; shader: " + c.message;
    return oneLine(line, 4000);
}

std::string xmlEscaped(const std::string& text, bool keepNewlines) {
    std::string out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = keepNewlines ? std::min(text.find('\n', start), text.size()) : text.size();
        if (start > 0) out += '\n';
        for (char ch : escapeControls(std::string_view(text).substr(start, end - start))) {
            switch (ch) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += ch;
            }
        }
        start = end + 1;
    }
    return out;
}

std::string base64(const std::string& bytes) {
    static const char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t v = 0;
        for (std::size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[(v >> (18 - 6 * k)) & 63u] : '=';
    }
    return out;
}

std::string junitXml(const TestRun& run) {
    // A run that could not start is one error case, so the CI's test view says why.
    const bool failedToStart = !run.runError.empty();
    const std::size_t tests = failedToStart ? 1 : run.cases.size();
    const std::size_t errors = failedToStart ? 1 : countOf(run, CaseOutcome::Error);
    const std::string counts = "tests=\"" + std::to_string(tests) + "\" failures=\"" +
                               std::to_string(failedToStart ? 0 : countOf(run, CaseOutcome::Differs)) + "\" errors=\"" +
                               std::to_string(errors) + "\"";
    // The suite's time is the sum of its cases' (what junit-10.xsd's consumers add up); the run's wall
    // clock is less, as references are compared on other threads while the next scene renders.
    double sum = 0;
    for (const TestCase& c : run.cases) sum += c.seconds;
    const std::string time = seconds(failedToStart ? run.seconds : sum);
    // "shadelab.screens" for --test path/to/screens/: what a CI's test view groups the cases under.
    // The folder's own name, also for "screens/", "." or "..": its absolute form, without a trailing '/'.
    std::error_code ec;
    fs::path dir = fs::weakly_canonical(fs::absolute(run.dir, ec), ec);
    if (ec || dir.filename().empty()) dir = fs::path(run.dir).lexically_normal();
    if (dir.filename().empty()) dir = dir.parent_path();
    const std::string classname = "shadelab." + dir.filename().string();
    const std::string suite =
        "shadelab --test " + shownPath(run.dir) + (run.shard.empty() ? "" : " --shard " + run.shard);
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"shadelab --test\" " << counts << " time=\""
      << time << "\">\n  <testsuite name=\"" << xmlEscaped(suite) << "\" " << counts << " skipped=\"0\" time=\"" << time
      << "\">\n";
    if (failedToStart)
        x << "    <testcase classname=\"" << xmlEscaped(classname) << "\" name=\"OpenGL\" time=\"" << time << "\">\n"
          << "      <error type=\"gl\" message=\"" << xmlEscaped("OpenGL cannot start: " + run.runError) << "\">"
          << xmlEscaped("no scene of " + run.dir + " was rendered: OpenGL cannot start: " + run.runError, true)
          << "</error>\n    </testcase>\n";
    for (const TestCase& c : run.cases) {  // (none when the run failed to start)
        x << "    <testcase classname=\"" << xmlEscaped(classname) << "\" name=\"" << xmlEscaped(c.name) << "\" time=\""
          << seconds(c.seconds) << "\"";
        if (c.outcome == CaseOutcome::Match) {
            x << "/>\n";
            continue;
        }
        const char* element = c.outcome == CaseOutcome::Differs ? "failure" : "error";
        const char* type = c.outcome == CaseOutcome::Differs ? "differs" : c.shaderError ? "shader" : "input";
        x << ">\n      <" << element << " type=\"" << type << "\" message=\"" << xmlEscaped(c.message) << "\">"
          << xmlEscaped("scene " + c.scenePath + "\nreference " + c.referencePath + "\n" + c.message +
                            (c.updated ? "\n--update: the reference was rewritten from this render" : ""),
                        true)
          << "</" << element << ">\n";
        // GitLab shows the first attachment in the merge request: the difference, else the render.
        std::string out = "scene " + c.scenePath + "\nreference " + c.referencePath;
        for (const std::string* a : {&c.differenceArtifact, &c.actualArtifact, &c.referenceArtifact})
            if (!a->empty()) out += "\n[[ATTACHMENT|" + *a + "]]";
        x << "      <system-out>" << xmlEscaped(out, true) << "</system-out>\n    </testcase>\n";
    }
    x << "  </testsuite>\n</testsuites>\n";
    return x.str();
}

float differenceFactorFor(int maxDiff) { return maxDiff > 0 ? 255.0f / float(maxDiff) : 1.0f; }

Image differenceForReport(const Image& actual, const Image& reference, float factor,
                          const std::vector<glm::ivec4>& masks) {
    Image d = amplifiedDifference(actual, reference, factor);
    // Hatched: diagonal grey stripes, 3 pixels of 8, over each masked rectangle (clipped to the image).
    for (const glm::ivec4& m : masks)
        for (int y = std::max(0, m.y); y < std::min(d.height, m.y + m.w); ++y)
            for (int x = std::max(0, m.x); x < std::min(d.width, m.x + m.z); ++x)
                if ((x + y) % 8 < 3) {
                    std::uint8_t* p = d.pixel(x, y);
                    p[0] = p[1] = p[2] = 128;
                    p[3] = 255;
                }
    return d;
}

namespace {

// Images at their own pixel size where they fit (width and height given; shrunk, never stretched, where
// three of them are wider than the page), never smoothed (pixelated), on a grey that shows where a
// render is transparent.
const char* const kStyle = R"(
body { font: 15px/1.45 system-ui, sans-serif; margin: 20px; color: #1b1b1b; background: #fff; }
h1 { font-size: 21px; margin: 0 0 4px; }
h1, h2, .meta, .verdict { overflow-wrap: anywhere; }
.meta { color: #555; margin: 0 0 16px; }
.verdict { font-size: 17px; font-weight: 600; padding: 8px 12px; border-radius: 4px; display: inline-block; }
.verdict.ok { background: #e3f4e1; color: #1d5e1a; }
.verdict.bad { background: #fde7e7; color: #8c1d18; }
section.case { border-left: 6px solid #c62828; background: #fff7f7; padding: 10px 14px; margin: 18px 0; }
section.case.error { border-left-color: #ef6c00; background: #fff8ef; }
section.case h2 { font-size: 18px; margin: 0 0 4px; }
.message { font-family: ui-monospace, monospace; font-size: 13px; white-space: pre-wrap; margin: 4px 0 10px; }
.images { display: flex; flex-wrap: wrap; gap: 18px; align-items: flex-start; }
figure { margin: 0; }
figcaption { font-size: 13px; color: #444; margin-bottom: 4px; }
/* Side by side, each shrunk to its share of the page when they are wider than it; a click shows one
   at its own pixel size (the row then scrolls). */
.images { flex-wrap: nowrap; overflow-x: auto; }
figure { flex: 0 1 auto; min-width: 0; }
figure.full { flex: none; }
img { display: block; max-width: 100%; height: auto; image-rendering: pixelated; background: #808080; cursor: zoom-in; }
figure.full img { max-width: none; cursor: zoom-out; }
table.passed { border-collapse: collapse; font-size: 13px; }
table.passed td { padding: 1px 14px 1px 0; }
)";

std::string dataImage(const std::string& png, const std::string& caption, const std::string& alt) {
    if (png.empty()) return "";
    // The PNG's own size from its IHDR chunk (bytes 16..23, big-endian): <img> drawn at exactly that size.
    const auto be32 = [&png](std::size_t at) {
        std::uint32_t v = 0;
        for (std::size_t k = 0; k < 4; ++k) v = v << 8 | static_cast<unsigned char>(png[at + k]);
        return v;
    };
    return "<figure onclick=\"this.classList.toggle('full')\"><figcaption>" + xmlEscaped(caption) +
           "</figcaption><img alt=\"" + xmlEscaped(alt) + "\" width=\"" + std::to_string(be32(16)) + "\" height=\"" +
           std::to_string(be32(20)) + "\" src=\"data:image/png;base64," + base64(png) + "\"></figure>";
}

std::string failingCase(const TestCase& c) {
    std::string h = std::string("<section class=\"case") + (c.outcome == CaseOutcome::Error ? " error" : "") +
                    "\" id=\"" + xmlEscaped(c.name) + "\"><h2>" + xmlEscaped(c.name) + ": " +
                    (c.outcome == CaseOutcome::Differs ? "differs" : "error") + "</h2>\n<div class=\"message\">" +
                    xmlEscaped(c.message) +
                    (c.updated ? "\n--update: the reference was rewritten from this render" : "") +
                    "</div>\n<div class=\"meta\">scene " + xmlEscaped(c.scenePath) + " &middot; reference " +
                    xmlEscaped(c.referencePath) + "</div>\n<div class=\"images\">";
    h += dataImage(c.referencePng, "reference", c.name + " reference");
    h += dataImage(c.actualPng, "this render", c.name + " render");
    char factor[32];
    std::snprintf(factor, sizeof factor, "%.4g", double(c.differenceFactor));
    const std::string largest = c.numbers ? std::to_string(c.numbers->maxDiff) + "/255" : "";
    h += dataImage(c.differencePng,
                   std::string("|render - reference| x ") + factor + " (the largest, " + largest + ", at full)" +
                       (c.masks.empty() ? "" : "; hatched: masked, not compared"),
                   c.name + " difference");
    return h + "</div></section>\n";
}

}  // namespace

std::string htmlReport(const TestRun& run) {
    const std::size_t failing = run.cases.size() - countOf(run, CaseOutcome::Match);
    const std::string title =
        "shadelab --test " + run.dir + (run.shard.empty() ? "" : " --shard " + run.shard) + ": " +
        (!run.runError.empty() ? std::string("OpenGL cannot start")
         : failing             ? std::to_string(failing) + " of " + std::to_string(run.cases.size()) + " failing"
                               : "all " + std::to_string(run.cases.size()) + " match");
    std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + xmlEscaped(title) +
                    "</title><style>" + kStyle + "</style></head><body>\n<h1>" + xmlEscaped(title) + "</h1>\n";
    h += "<p class=\"meta\">scenes " + xmlEscaped(run.dir) + " &middot; references " + xmlEscaped(run.referencesDir) +
         (run.shaderDir.empty() ? "" : " &middot; shaders " + xmlEscaped(run.shaderDir)) + " &middot; limits: max " +
         std::to_string(run.tolerance.maxDiff) + "/255, mean " + formatNumber(run.tolerance.meanDiff) +
         "/255 &middot; " + seconds(run.seconds) + " s</p>\n";
    if (!run.runError.empty())
        return h + "<p class=\"verdict bad\">" +
               xmlEscaped("no scene was rendered: OpenGL cannot start: " + run.runError) + "</p>\n</body></html>\n";
    h += std::string("<p class=\"verdict ") + (failing ? "bad" : "ok") + "\">" +
         xmlEscaped(summaryLine(run).substr(std::string("shadelab: ").size())) + "</p>\n";
    for (const TestCase& c : run.cases)
        if (c.outcome != CaseOutcome::Match) h += failingCase(c);
    if (failing < run.cases.size()) {
        h += "<h2>Matching (" + std::to_string(run.cases.size() - failing) + ")</h2>\n<table class=\"passed\">";
        for (const TestCase& c : run.cases)
            if (c.outcome == CaseOutcome::Match)
                h += "<tr><td>" + xmlEscaped(c.name) + "</td><td>" +
                     (c.numbers ? xmlEscaped(describe(*c.numbers, c.tolerance)) : "") + "</td></tr>\n";
        h += "</table>\n";
    }
    return h + "</body></html>\n";
}

}  // namespace shadelab
