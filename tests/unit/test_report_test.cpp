// The --test run's reports without GL (run/test_report.hpp): the summary line, JUnit XML and the HTML
// page made from a hand-built run, and the escaping and base64 they rest on.
#include "run/test_report.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include <string>

using namespace shadelab;

namespace {

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

// Three cases: one matches, one differs by numbers over the limits, one is a shader that did not compile.
TestRun sampleRun() {
    TestRun run;
    run.dir = "tests/scenes/";
    run.referencesDir = "refs";
    run.seconds = 1.5;
    TestCase match;
    match.name = "a_match";
    match.outcome = CaseOutcome::Match;
    match.numbers = CompareResult{};
    match.numbers->sizeMatches = true;
    match.seconds = 0.25;
    TestCase differs;
    differs.name = "b<&>\"'";
    differs.scenePath = "scenes/b.json";
    differs.referencePath = "refs/b.png";
    differs.outcome = CaseOutcome::Differs;
    differs.seconds = 0.5;
    differs.differenceArtifact = "art/b.diff.png";
    differs.actualArtifact = "art/b.actual.png";
    differs.message = "max 9/255 (limit 4), mean 0.0157 (limit 0.002)";
    Image pixel(3, 2);
    differs.actualPng = differs.referencePng = differs.differencePng = encodePng(pixel);
    TestCase shader;
    shader.name = "c_shader";
    shader.outcome = CaseOutcome::Error;
    shader.shaderError = true;
    shader.seconds = 0.25;
    shader.message = "program flat, fragment stage (flat.frag, GLSL 330 core) failed to compile: flat.frag:7: error";
    TestCase again = shader;
    again.name = "d_shader";
    again.seconds = 0.125;
    run.cases = {match, differs, shader, again};
    return run;
}

}  // namespace

TEST(TestReport, EscapingAndBase64) {
    EXPECT_EQ(xmlEscaped("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
    EXPECT_EQ(xmlEscaped("line\none\x01"), "line\\none\\x01");  // XML 1.0 has no place for \x01
    EXPECT_EQ(xmlEscaped("line\none", true), "line\none");
    // RFC 4648's test vectors.
    const char* const vectors[][2] = {{"", ""},         {"f", "Zg=="},         {"fo", "Zm8="},    {"foo", "Zm9v"},
                                      {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="}, {"foobar", "Zm9vYmFy"}};
    for (const auto& v : vectors) EXPECT_EQ(base64(v[0]), v[1]);
    EXPECT_EQ(base64(std::string("\xff\xfe", 2)), "//4=");
}

TEST(TestReport, SummaryNamesTheFailingCasesAndEachShaderErrorOnce) {
    const TestRun run = sampleRun();
    EXPECT_EQ(summaryLine(run), "shadelab: --test tests/scenes/: 4 scenes, 1 match, 1 differs (b<&>\"'), 2 errors (c_shader, "
                                "d_shader); shader: " + run.cases[2].message);
    EXPECT_EQ(caseLine(run, run.cases[1]), "shadelab: --test tests/scenes/: b<&>\"': differs: " + run.cases[1].message);
    TestRun allMatch = run;
    allMatch.cases = {run.cases[0]};
    EXPECT_EQ(summaryLine(allMatch), "shadelab: --test tests/scenes/: 1 scene, 1 match");
}

TEST(TestReport, JunitHasOneTestcasePerSceneAndTheNumbers) {
    const std::string xml = junitXml(sampleRun());
    EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites ", 0), 0u) << xml;
    // The suite's time is its cases' sum (1.125 s), not the run's wall clock (1.5 s: comparing overlaps rendering).
    EXPECT_NE(xml.find("<testsuite name=\"shadelab --test tests/scenes/\" tests=\"4\" failures=\"1\" errors=\"2\" skipped=\"0\" "
                       "time=\"1.125\">"),
              std::string::npos)
        << xml;
    EXPECT_EQ(occurrences(xml, "<testcase "), 4u);
    EXPECT_EQ(occurrences(xml, "<failure "), 1u);
    EXPECT_EQ(occurrences(xml, "<error "), 2u);
    EXPECT_NE(xml.find("name=\"b&lt;&amp;&gt;&quot;&#39;\""), std::string::npos) << xml;
    EXPECT_NE(xml.find("<failure type=\"differs\" message=\"max 9/255 (limit 4), mean 0.0157 (limit 0.002)\">"),
              std::string::npos)
        << xml;
    EXPECT_NE(xml.find("<error type=\"shader\" message=\"program flat, fragment stage (flat.frag, GLSL 330 core) failed "
                       "to compile: flat.frag:7: error\">"),
              std::string::npos)
        << xml;
    // No testcase@file: Jenkins xunit's schema (junit-10.xsd) allows none.
    EXPECT_NE(xml.find("<testcase classname=\"shadelab.scenes\" name=\"a_match\" time=\"0.250\"/>"), std::string::npos)
        << xml;
    EXPECT_EQ(xml.find(" file="), std::string::npos) << xml;
    // The paths and --artifacts in system-out, the difference first (GitLab shows the first attachment).
    EXPECT_NE(xml.find("<system-out>scene scenes/b.json\nreference refs/b.png\n[[ATTACHMENT|art/b.diff.png]]\n"
                       "[[ATTACHMENT|art/b.actual.png]]</system-out>"),
              std::string::npos)
        << xml;
    EXPECT_EQ(xml.find("b<&"), std::string::npos);  // nothing unescaped
}

// `--test .` (or ..): the classname is the folder's own name, not "shadelab.." .
TEST(TestReport, JunitClassnameIsTheFoldersName) {
    TestRun run = sampleRun();
    run.dir = ".";
    const std::string here = std::filesystem::current_path().filename().string();
    EXPECT_NE(junitXml(run).find("classname=\"shadelab." + here + "\""), std::string::npos) << junitXml(run);
}

TEST(TestReport, HtmlShowsTheFailingCasesImagesAtTheirSize) {
    const TestRun run = sampleRun();
    const std::string html = htmlReport(run);
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
    // The differing case: three images, 3x2 as the PNG says, inline.
    EXPECT_EQ(occurrences(html, "width=\"3\" height=\"2\" src=\"data:image/png;base64," + base64(run.cases[1].actualPng) + "\""),
              3u);
    EXPECT_NE(html.find("<h2>b&lt;&amp;&gt;&quot;&#39;: differs</h2>"), std::string::npos);
    EXPECT_NE(html.find("<h2>c_shader: error</h2>"), std::string::npos);
    EXPECT_NE(html.find(xmlEscaped(run.cases[2].message)), std::string::npos);
    EXPECT_NE(html.find("<tr><td>a_match</td><td>max 0/255 (limit 4), mean 0 (limit 0.002)</td></tr>"), std::string::npos);
    EXPECT_EQ(html.find("b<&"), std::string::npos);
}

// OpenGL that cannot start: one error case that says why, whatever cases were found.
TEST(TestReport, RunThatCannotStartIsOneError) {
    TestRun run = sampleRun();
    run.cases.clear();
    run.runError = "no headless OpenGL: headless rendering needs libOSMesa.so.8";
    const std::string xml = junitXml(run);
    EXPECT_NE(xml.find("tests=\"1\" failures=\"0\" errors=\"1\""), std::string::npos) << xml;
    EXPECT_NE(xml.find("<testcase classname=\"shadelab.scenes\" name=\"OpenGL\" time=\"1.500\">\n      <error type=\"gl\" "
                       "message=\"OpenGL cannot start: no headless OpenGL: headless rendering needs libOSMesa.so.8\">"),
              std::string::npos)
        << xml;
    EXPECT_NE(htmlReport(run).find("OpenGL cannot start: no headless OpenGL"), std::string::npos);
}

// --update: the cases it rewrote are "written", not errors or differences.
TEST(TestReport, UpdateSummarySaysWritten) {
    TestRun run = sampleRun();
    run.cases[1].updated = true;
    const std::string line = summaryLine(run);
    EXPECT_EQ(line.rfind("shadelab: --test tests/scenes/: 4 scenes, 1 match, 1 written (b<&>\"'), 2 errors (c_shader, d_shader)", 0),
              0u)
        << line;
}
