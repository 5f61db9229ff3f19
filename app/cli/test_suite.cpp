#include "cli/test_suite.hpp"

#include "cli/reference.hpp"
#include "cli/test_report.hpp"
#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/base/message.hpp"
#include "core/scene/playlist.hpp"
#include "headless/headless.hpp"

#include <algorithm>
#include <chrono>
#include <deque>
#include <filesystem>
#include <future>
#include <iostream>
#include <thread>

namespace shadelab {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::vector<std::string> sceneFiles(const std::string& dir) {
    std::error_code ec;
    if (!fs::exists(dir, ec)) throw InputError("--test: " + dir + ": no such folder");
    if (!fs::is_directory(dir, ec)) throw InputError("--test: " + dir + ": not a folder (--test takes a folder of scene files)");
    try {
        return listPresetFiles(dir);
    } catch (const InputError& e) {
        throw InputError(std::string("--test: ") + e.what());
    }
}

// Every case of the folder, its scene loaded with the command line's overrides; a scene that cannot be
// read (or takes an override badly) is an error case with no scene to render.
std::vector<TestCase> loadCases(const TestRun& run, const Options& options, std::vector<Scene>& scenes,
                                std::vector<std::size_t>& caseOfScene) {
    std::vector<TestCase> cases;
    for (const std::string& path : sceneFiles(run.dir)) {
        TestCase c;
        c.scenePath = path;
        try {
            Preset p = loadPreset(path, [&options](Scene& s) { applyOverrides(s, options); });
            c.name = p.name;
            c.diffFactor = p.scene.diff.factor;
            scenes.push_back(std::move(p.scene));
            caseOfScene.push_back(cases.size());
        } catch (const InputError& e) {
            const std::string file = fs::path(path).filename().string();
            c.name = file.substr(0, file.size() - 5);  // less ".json" (listPresetFiles lists no other)
            c.message = e.what();
        }
        c.referencePath = (fs::path(run.referencesDir) / (c.name + ".png")).string();
        cases.push_back(std::move(c));
    }
    return cases;
}

// The CPU work of a rendered case, on a worker thread: its reference read and compared, the report's
// PNGs made for a case that does not match, and with --update its reference rewritten.
void compareCase(TestCase& c, const Image& actual, const Options& options, const ReferenceTolerance& tolerance) {
    const auto start = Clock::now();
    std::optional<Image> reference;
    std::error_code ec;
    if (!fs::exists(c.referencePath, ec) && !ec) {
        c.message = "the reference " + c.referencePath + " does not exist (--update writes it from this render)";
    } else {
        try {
            reference = readPng(c.referencePath);
        } catch (const InputError& e) {
            c.message = std::string("the reference: ") + e.what();
        }
    }
    if (reference) {
        const CompareResult r = compareImages(actual, *reference, 0);
        c.outcome = tolerance.matches(r) ? CaseOutcome::Match : CaseOutcome::Differs;
        if (r.sizeMatches) c.numbers = r, c.message = comparisonText(r, tolerance);
        else c.message = "size " + sizeText(actual) + ", the reference's " + sizeText(*reference);
    }
    if (c.outcome != CaseOutcome::Match) {
        if (options.report) {
            c.actualPng = encodePng(actual);
            if (reference) c.referencePng = encodePng(*reference);
            if (c.numbers) c.differencePng = encodePng(amplifiedDifference(actual, *reference, c.diffFactor));
        }
        if (options.update) {
            writePng(c.referencePath, actual, 9);  // references are committed: the smallest files
            c.updated = true;
        }
    }
    c.seconds += secondsSince(start);
}

// Renders the scenes on one context, each render's comparison handed to a worker thread (at most as many
// waiting as the machine has cores) while the next scene renders.
void renderAndCompare(TestRun& run, std::vector<Scene>& scenes, const std::vector<std::size_t>& caseOfScene,
                      const Options& options, const ShaderLibrary& shaders, HeadlessBackend backend, int msaaSamples) {
    const std::size_t workers = std::max(1u, std::thread::hardware_concurrency());
    std::deque<std::future<void>> pending;
    auto last = Clock::now();
    const auto rendered = [&](std::size_t i, Image image) {
        TestCase& c = run.cases[caseOfScene[i]];
        c.seconds = secondsSince(last);
        last = Clock::now();
        if (pending.size() >= workers) pending.front().get(), pending.pop_front();
        pending.push_back(std::async(std::launch::async, [&c, &options, &run, image = std::move(image)] {
            compareCase(c, image, options, run.tolerance);
        }));
    };
    const auto failed = [&](std::size_t i, const std::exception& e) {
        TestCase& c = run.cases[caseOfScene[i]];
        c.seconds = secondsSince(last);
        last = Clock::now();
        c.shaderError = dynamic_cast<const ShaderError*>(&e) != nullptr;
        c.message = c.shaderError ? joinedLines(e.what()) : std::string(e.what());
    };
    // The frames waiting for their comparison, for the memory budget.
    std::uint64_t largest = 0;
    for (const Scene& s : scenes) largest = std::max(largest, 4 * std::uint64_t(s.width) * std::uint64_t(s.height));
    try {
        renderScenesHeadless(scenes, shaders, backend, rendered, msaaSamples, workers * largest, failed);
    } catch (...) {
        for (std::future<void>& f : pending) f.wait();  // they refer to `run`
        throw;
    }
    for (std::future<void>& f : pending) f.get();
}

void writeText(const std::string& path, const std::string& text) {
    writeFileAtomic(path, [&text](std::FILE* f) { return std::fwrite(text.data(), 1, text.size(), f) == text.size(); });
}

}  // namespace

int runTestSuite(const Options& options, const ShaderLibrary& shaders, HeadlessBackend backend, int msaaSamples) {
    const auto start = Clock::now();
    TestRun run;
    run.dir = *options.testDir;
    run.referencesDir = options.referencesDir.value_or(run.dir);
    run.shaderDir = options.shaderDir;
    run.tolerance = referenceTolerance(options);
    std::error_code ec;
    if (options.referencesDir && !fs::is_directory(run.referencesDir, ec))
        throw InputError("--references: " + run.referencesDir + ": no such folder");  // (--update creates no folders)
    std::vector<Scene> scenes;
    std::vector<std::size_t> caseOfScene;
    run.cases = loadCases(run, options, scenes, caseOfScene);
    renderAndCompare(run, scenes, caseOfScene, options, shaders, backend, msaaSamples);
    run.seconds = secondsSince(start);

    bool allWell = true;  // every case matches, or had its reference rewritten
    for (const TestCase& c : run.cases) {
        if (c.outcome == CaseOutcome::Match) continue;
        std::cout << caseLine(run, c) << "\n";
        if (c.updated) std::cout << oneLine("shadelab: --test " + run.dir + ": " + c.name + ": --update: wrote " +
                                            c.referencePath + " from this render") << "\n";
        allWell = allWell && c.updated;
    }
    for (const auto& [file, text] : {std::pair{options.junit, &junitXml}, std::pair{options.report, &htmlReport}}) {
        if (!file) continue;
        writeText(*file, text(run));
        if (options.verbose) std::cerr << "shadelab: wrote " << *file << "\n";
    }
    std::cout << summaryLine(run) << std::endl;
    return allWell ? 0 : 1;
}

}  // namespace shadelab
