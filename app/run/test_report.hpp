#pragma once
// What a `--test DIR` run found (run/test_suite.hpp runs it) and how it is told: a line per failing case
// and a summary on stdout, JUnit XML (--junit) and one self-contained HTML page (--report). GL-free, so
// the writers are unit-tested without a context (tests/unit/test_report_test.cpp).
//
// A case is one scene file. It MATCHES its reference, DIFFERS from it (the numbers are over a threshold,
// or the sizes differ: JUnit's <failure>), or is an ERROR: it could not be compared at all (the scene
// cannot be read, a shader does not compile, the reference is missing or not a PNG: JUnit's <error>).
// Either way the run goes on with the next scene.
#include "core/image/image.hpp"

#include <glm/vec4.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

enum class CaseOutcome { Match, Differs, Error };

struct TestCase {
    std::string name;           // the scene's path in DIR without .json ("phong", "lights/area"), '/' between folders
    std::string scenePath;      // DIR/NAME.json, relative to the folder shadelab runs in where it is inside it
    std::string referencePath;  // DIR/NAME.png, or --references DIR2/NAME.png, likewise
    CaseOutcome outcome = CaseOutcome::Error;
    // Why it differs or could not be compared (one line; a compiler log's lines joined), empty when it matches.
    std::string message;
    bool shaderError = false;              // the message is a ShaderError's (the summary repeats it once)
    std::optional<CompareResult> numbers;  // when it was compared (same size), the masks left out
    ImageTolerance tolerance;              // the run's, or the scene's own "test" settings
    std::vector<glm::ivec4> masks;         // the scene's "test": "masks", [x, y, w, h] left out of the comparison
    double seconds = 0;                    // render, reading the reference and comparing
    bool updated = false;                  // --update rewrote its reference from this render
    // For the HTML report, of a case that does not match: the images as PNG files' bytes, each empty
    // where there is none (no render, no readable reference, sizes that differ have no difference).
    std::string referencePng, actualPng, differencePng;
    float differenceFactor = 1;  // the difference image is |render - reference| x this (the largest shown at full)
    // --artifacts: the files written for this case (render, difference, reference), each empty when none.
    std::string actualArtifact, differenceArtifact, referenceArtifact;
};

struct TestRun {
    std::string dir;            // --test DIR as given
    std::string referencesDir;  // --references DIR2, or DIR
    std::string shaderDir;      // --shader-dir, empty when not given
    std::string shard;          // --shard K/N as given, empty when not given
    ImageTolerance tolerance;
    std::vector<TestCase> cases;  // in name order
    double seconds = 0;           // the whole run, wall-clock
    // Set when the run could not start at all (OpenGL cannot start): the reason. JUnit then holds one
    // error case saying so, the page says so, and no case was run.
    std::string runError;
};

std::size_t countOf(const TestRun& run, CaseOutcome outcome);

// `path` as the reports give it: relative to the folder shadelab runs in where it is inside it (what a
// CI's artefacts and GitLab's links expect: the project's folder), else as it is; '/' between folders.
std::string shownPath(const std::filesystem::path& path);

// "shadelab: --test DIR: NAME: differs: max 9/255 (limit 4), mean 0.0157 (limit 0.002)": for each case
// that does not match.
std::string caseLine(const TestRun& run, const TestCase& c);
// "shadelab: --test DIR: 12 scenes, 10 match, 1 differs (a), 1 error (b)", then each distinct shader
// error once ("; shader: program flat, fragment stage (flat.frag, ...) failed to compile: flat.frag:7: ...").
std::string summaryLine(const TestRun& run);

// The JUnit XML document: <testsuites> with one <testsuite> (tests, failures, errors, time: the sum of
// the cases' times) and one <testcase> per scene (classname "shadelab.FOLDER", FOLDER the last part of
// DIR), a <failure> or <error> whose message has the numbers or the reason, and a <system-out> with
// the scene's and the reference's paths and the --artifacts as [[ATTACHMENT|path]] (GitLab shows the
// first). Valid against Jenkins xunit's junit-10.xsd (tests/cli/junit-xunit.xsd states its constraints),
// which allows a testcase no `file` attribute: GitLab's link to the file is given up for it.
std::string junitXml(const TestRun& run);
// The HTML page: the summary, each failing case with its images side by side (data: URIs, shrunk to the
// page's width when wide, full size on a click; the difference scaled so the largest is at full
// brightness, the masks hatched), the matching cases listed.
std::string htmlReport(const TestRun& run);

// The difference image of a comparison, as the page and --artifacts show it: per channel
// |render - reference| x `factor` (255 / the largest difference: that one at full brightness), the
// masked rectangles hatched grey.
Image differenceForReport(const Image& actual, const Image& reference, float factor,
                          const std::vector<glm::ivec4>& masks);
// The factor that brings a largest difference of `maxDiff` /255 to 255 (1 when nothing differs).
float differenceFactorFor(int maxDiff);

// Text escaped for XML and HTML (&, <, >, ", '), control characters and bytes that are not UTF-8 as
// message.hpp's escapeControls writes them (XML 1.0 allows neither); newlines kept when `keepNewlines`.
std::string xmlEscaped(const std::string& text, bool keepNewlines = false);
// Base64 (RFC 4648, with padding), for data: URIs.
std::string base64(const std::string& bytes);

}  // namespace shadelab
