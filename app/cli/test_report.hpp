#pragma once
// What a `--test DIR` run found (cli/test_suite.hpp runs it) and how it is told: a line per failing case
// and a summary on stdout, JUnit XML (--junit) and one self-contained HTML page (--report). GL-free, so
// the writers are unit-tested without a context (tests/unit/test_report_test.cpp).
//
// A case is one scene file. It MATCHES its reference, DIFFERS from it (the numbers are over a threshold,
// or the sizes differ: JUnit's <failure>), or is an ERROR: it could not be compared at all (the scene
// cannot be read, a shader does not compile, the reference is missing or not a PNG: JUnit's <error>).
// Either way the run goes on with the next scene.
#include "core/image/image.hpp"

#include <optional>
#include <string>
#include <vector>

namespace shadelab {

enum class CaseOutcome { Match, Differs, Error };

struct TestCase {
    std::string name;           // the scene file's name without .json
    std::string scenePath;      // DIR/NAME.json
    std::string referencePath;  // DIR/NAME.png, or --references DIR2/NAME.png
    CaseOutcome outcome = CaseOutcome::Error;
    // Why it differs or could not be compared (one line; a compiler log's lines joined), empty when it matches.
    std::string message;
    bool shaderError = false;              // the message is a ShaderError's (the summary repeats it once)
    std::optional<CompareResult> numbers;  // when it was compared (same size)
    double seconds = 0;                    // render, reading the reference and comparing
    bool updated = false;                  // --update rewrote its reference from this render
    // For the HTML report, of a case that does not match: the images as PNG files' bytes, each empty
    // where there is none (no render, no readable reference, sizes that differ have no difference).
    std::string referencePng, actualPng, differencePng;
    float diffFactor = 1;  // the scene's diff.factor, which amplified the difference
};

struct TestRun {
    std::string dir;             // --test DIR as given
    std::string referencesDir;   // --references DIR2, or DIR
    std::string shaderDir;       // --shader-dir, empty when not given
    ReferenceTolerance tolerance;
    std::vector<TestCase> cases; // in file-name order
    double seconds = 0;          // the whole run
};

std::size_t countOf(const TestRun& run, CaseOutcome outcome);

// "shadelab: --test DIR: NAME: differs: max 9/255 (limit 4), mean 0.0157 (limit 0.002)": for each case
// that does not match.
std::string caseLine(const TestRun& run, const TestCase& c);
// "shadelab: --test DIR: 12 scenes, 10 match, 1 differs (a), 1 error (b)", then each distinct shader
// error once ("; shader: program flat, fragment stage (flat.frag, ...) failed to compile: flat.frag:7: ...").
std::string summaryLine(const TestRun& run);

// The JUnit XML document: <testsuites> with one <testsuite> (tests, failures, errors, time) and one
// <testcase> per scene (classname "shadelab.FOLDER", FOLDER the last part of DIR), a <failure> or <error>
// whose message has the numbers or the reason.
std::string junitXml(const TestRun& run);
// The HTML page: the summary, each failing case with its images side by side (data: URIs, at their own
// pixel size), the matching cases listed.
std::string htmlReport(const TestRun& run);

// Text escaped for XML and HTML (&, <, >, ", '), control characters and bytes that are not UTF-8 as
// message.hpp's escapeControls writes them (XML 1.0 allows neither); newlines kept when `keepNewlines`.
std::string xmlEscaped(const std::string& text, bool keepNewlines = false);
// Base64 (RFC 4648, with padding), for data: URIs.
std::string base64(const std::string& bytes);

}  // namespace shadelab
