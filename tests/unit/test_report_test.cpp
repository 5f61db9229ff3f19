// The --test run's reports without GL (cli/test_report.hpp): the summary line, JUnit XML and the HTML
// page made from a hand-built run, and the escaping and base64 they rest on.
#include "cli/test_report.hpp"

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
    TestCase differs;
    differs.name = "b<&>\"'";
    differs.scenePath = "scenes/b.json";
    differs.referencePath = "refs/b.png";
    differs.outcome = CaseOutcome::Differs;
    differs.message = "max 9/255 (limit 4), mean 0.0157 (limit 0.002)";
    Image pixel(3, 2);
    differs.actualPng = differs.referencePng = differs.differencePng = encodePng(pixel);
    TestCase shader;
    shader.name = "c_shader";
    shader.outcome = CaseOutcome::Error;
    shader.shaderError = true;
    shader.message = "program flat, fragment stage (flat.frag, GLSL 330 core) failed to compile: flat.frag:7: error";
    TestCase again = shader;
    again.name = "d_shader";
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
    EXPECT_NE(xml.find("<testsuite name=\"shadelab --test tests/scenes/\" tests=\"4\" failures=\"1\" errors=\"2\" skipped=\"0\" "
                       "time=\"1.500\">"),
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
    EXPECT_NE(xml.find("<testcase classname=\"shadelab.scenes\" name=\"a_match\" file=\"\" time=\"0.000\"/>"),
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
