#include "run/test_suite.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/base/message.hpp"
#include "core/scene/playlist.hpp"
#include "headless/headless.hpp"
#include "run/reference.hpp"
#include "run/test_report.hpp"

#include <algorithm>
#include <chrono>
#include <deque>
#include <filesystem>
#include <future>
#include <iostream>
#include <set>
#include <thread>

namespace shadelab {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Files of `dir` and its subfolders whose names end in `extension` (any case), hidden ones (and hidden
// folders) left out, as paths relative to `dir` with '/' between folders, sorted byte by byte.
std::vector<std::string> filesUnder(const fs::path& dir, const char* extension) {
    std::vector<std::string> names;
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        std::error_code typeError;
        if (!name.empty() && name[0] == '.') {
            if (it->is_directory(typeError)) it.disable_recursion_pending();
            continue;
        }
        if (!hasExtension(name, extension) || it->is_directory(typeError)) continue;
        names.push_back(it->path().lexically_relative(dir).generic_string());
    }
    if (ec) throw InputError("--test: " + dir.string() + ": cannot read the folder: " + ec.message());
    std::sort(names.begin(), names.end());
    return names;
}

// The scene files of DIR and its subfolders (relative names, sorted).
std::vector<std::string> sceneFiles(const std::string& dir) {
    std::error_code ec;
    if (!fs::exists(dir, ec)) throw InputError("--test: " + dir + ": no such folder");
    if (!fs::is_directory(dir, ec))
        throw InputError("--test: " + dir + ": not a folder (--test takes a folder of scene files)");
    std::vector<std::string> files = filesUnder(dir, ".json");
    if (files.empty()) throw InputError("--test: " + dir + ": no scene files (*.json) in the folder or its subfolders");
    return files;
}

// "x.json" less its extension (hasExtension matched it in any case).
std::string withoutExtension(const std::string& name, std::size_t extension) {
    return name.substr(0, name.size() - extension);
}

// A glob: `*` any characters ('/' too), `?` one, everything else itself.
bool globMatches(const char* pattern, const char* text) {
    for (; *pattern; ++pattern, ++text) {
        if (*pattern == '*') {
            for (const char* rest = text;; ++rest) {
                if (globMatches(pattern + 1, rest)) return true;
                if (!*rest) return false;
            }
        }
        if (!*text || (*pattern != '?' && *pattern != *text)) return false;
    }
    return !*text;
}

// The shard (0..n-1) a case belongs to: FNV-1a (64-bit) of its name, so it never depends on the other
// cases; a case added or removed moves no other one.
int shardOf(const std::string& name, int n) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char ch : name) h = (h ^ ch) * 1099511628211ull;
    return int(h % std::uint64_t(n));
}

// The case names of the folder that this run takes: --filter (any pattern), then --shard.
std::vector<std::string> selectedNames(const std::vector<std::string>& names, const Options& options) {
    std::vector<std::string> picked;
    std::vector<bool> used(options.filters.size(), false);
    for (const std::string& name : names) {
        bool matches = options.filters.empty();
        for (std::size_t f = 0; f < options.filters.size(); ++f)
            if (globMatches(options.filters[f].c_str(), name.c_str())) matches = used[f] = true;
        if (!matches) continue;
        if (options.shard && shardOf(name, options.shard->second) != options.shard->first - 1) continue;
        picked.push_back(name);
    }
    for (std::size_t f = 0; f < options.filters.size(); ++f)
        if (!used[f])
            throw InputError("--filter: \"" + quoteInput(options.filters[f]) + "\" matches no case of " +
                             *options.testDir + " (--list names them)");
    return picked;
}

// The run's thresholds with the scene's own "test" settings over them.
ImageTolerance toleranceOf(const ImageTolerance& run, const TestSettings& t) {
    ImageTolerance r = run;
    if (t.maxDiff) r.maxDiff = *t.maxDiff;
    if (t.meanDiff) r.meanDiff = *t.meanDiff;
    if (t.maxDiffPixels) r.maxDiffPixels = *t.maxDiffPixels;
    return r;
}

// Every case this run takes, its scene loaded with the command line's overrides; a scene that cannot be
// read (or takes an override badly) is an error case with no scene to render.
std::vector<TestCase> loadCases(const TestRun& run, const std::vector<std::string>& names, const Options& options,
                                std::vector<Scene>& scenes, std::vector<std::size_t>& caseOfScene) {
    std::vector<TestCase> cases;
    for (const std::string& name : names) {
        TestCase c;
        c.name = name;
        c.scenePath = shownPath(fs::path(run.dir) / (name + ".json"));  // also what its messages name
        c.referencePath = shownPath(fs::path(run.referencesDir) / (name + ".png"));
        c.tolerance = run.tolerance;
        try {
            Preset p = loadPreset(c.scenePath, [&options](Scene& s) { applyOverrides(s, options); });
            c.tolerance = toleranceOf(run.tolerance, p.scene.test);
            c.masks = p.scene.test.masks;
            scenes.push_back(std::move(p.scene));
            caseOfScene.push_back(cases.size());
        } catch (const InputError& e) {
            c.message = e.what();
        }
        cases.push_back(std::move(c));
    }
    return cases;
}

// The references under --references (or DIR) that no scene of the whole folder has: left behind by a
// renamed or removed scene. One warning line on stderr.
void warnAboutOrphans(const TestRun& run, const std::vector<std::string>& sceneNames, const Options& options) {
    const std::set<std::string> scenes(sceneNames.begin(), sceneNames.end());
    std::vector<std::string> orphans;
    std::error_code ec;
    const fs::path artifacts = options.artifacts ? fs::weakly_canonical(*options.artifacts, ec) : fs::path();
    if (!fs::is_directory(run.referencesDir, ec)) return;
    for (const std::string& png : filesUnder(run.referencesDir, ".png")) {
        if (scenes.count(withoutExtension(png, 4))) continue;
        // --artifacts inside the references: its own files are no references.
        const fs::path inArtifacts =
            fs::weakly_canonical(fs::path(run.referencesDir) / png, ec).lexically_relative(artifacts);
        if (!artifacts.empty() && !inArtifacts.empty() && *inArtifacts.begin() != "..") continue;
        orphans.push_back(png);
    }
    if (orphans.empty()) return;
    std::string list;
    for (std::size_t i = 0; i < orphans.size() && i < 8; ++i) list += (i ? ", " : "") + orphans[i];
    if (orphans.size() > 8) list += " and " + std::to_string(orphans.size() - 8) + " more";
    std::cerr << oneLine("shadelab: warning: --test " + run.dir + ": " + std::to_string(orphans.size()) + " reference" +
                         (orphans.size() == 1 ? " has" : "s have") + " no scene in " + run.dir + ": " + list)
              << "\n";
}

// `image` masked: the masks' pixels taken from `reference`, so they add no difference.
Image masked(const Image& image, const Image& reference, const std::vector<glm::ivec4>& masks,
             std::size_t& maskedPixels) {
    Image out = image;
    std::vector<bool> hidden(std::size_t(image.width) * std::size_t(image.height), false);
    for (const glm::ivec4& m : masks)
        for (int y = std::max(0, m.y); y < std::min(image.height, m.y + m.w); ++y)
            for (int x = std::max(0, m.x); x < std::min(image.width, m.x + m.z); ++x)
                hidden[std::size_t(y) * std::size_t(image.width) + std::size_t(x)] = true;
    maskedPixels = std::size_t(std::count(hidden.begin(), hidden.end(), true));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (hidden[std::size_t(y) * std::size_t(image.width) + std::size_t(x)])
                std::copy(reference.pixel(x, y), reference.pixel(x, y) + 4, out.pixel(x, y));
    return out;
}

// The comparison of a case: the masks left out, the mean over the pixels that are compared.
CompareResult compareCaseImages(const Image& actual, const Image& reference, const std::vector<glm::ivec4>& masks) {
    if (masks.empty() || actual.width != reference.width || actual.height != reference.height)
        return compareImages(actual, reference, 0);
    std::size_t maskedPixels = 0;
    CompareResult r = compareImages(masked(actual, reference, masks, maskedPixels), reference, 0);
    const double all = double(actual.width) * double(actual.height), compared = all - double(maskedPixels);
    r.meanDiff = compared > 0 ? r.meanDiff * all / compared : 0.0;
    return r;
}

// Writes `path`, making its folder first (a case in a subfolder; a new --references or --artifacts).
void writePngMakingFolder(const fs::path& path, const Image& image, int level) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    writePng(path.string(), image, level);
}

// The CPU work of a rendered case, on a worker thread: its reference read and compared, the report's
// and --artifacts' PNGs made for a case that does not match, and with --update its reference rewritten.
void compareCase(TestCase& c, const Image& actual, const Options& options) {
    const auto start = Clock::now();
    const fs::path referencePath = c.referencePath;  // (relative to where shadelab runs: as its messages name it)
    std::optional<Image> reference;
    std::error_code ec;
    if (!fs::exists(referencePath, ec) && !ec) {
        c.message = "the reference " + c.referencePath + " does not exist (--update writes it from this render)";
    } else {
        try {
            reference = readPng(c.referencePath);
        } catch (const InputError& e) {
            c.message = std::string("the reference: ") + e.what();
        }
    }
    if (reference) {
        const CompareResult r = compareCaseImages(actual, *reference, c.masks);
        c.outcome = c.tolerance.matches(r) ? CaseOutcome::Match : CaseOutcome::Differs;
        if (r.sizeMatches) {
            c.numbers = r;
            c.message = describe(r, c.tolerance);
        } else {
            c.message = "size " + sizeText(actual) + ", the reference's " + sizeText(*reference);
        }
    }
    if (c.outcome != CaseOutcome::Match) {
        std::optional<Image> difference;
        if (c.numbers) {
            c.differenceFactor = differenceFactorFor(c.numbers->maxDiff);
            difference = differenceForReport(actual, *reference, c.differenceFactor, c.masks);
        }
        if (options.report) {
            c.actualPng = encodePng(actual);
            if (reference) c.referencePng = encodePng(*reference);
            if (difference) c.differencePng = encodePng(*difference);
        }
        if (options.artifacts) {
            const fs::path base = fs::path(*options.artifacts) / c.name;
            const auto artifact = [&base](const char* suffix) { return fs::path(base.string() + suffix); };
            writePngMakingFolder(artifact(".actual.png"), actual, 1);
            c.actualArtifact = shownPath(artifact(".actual.png"));
            if (difference) {
                writePngMakingFolder(artifact(".diff.png"), *difference, 1);
                c.differenceArtifact = shownPath(artifact(".diff.png"));
            }
            if (reference) {  // the file itself, byte for byte
                fs::copy_file(referencePath, artifact(".reference.png"), fs::copy_options::overwrite_existing, ec);
                if (!ec) c.referenceArtifact = shownPath(artifact(".reference.png"));
            }
        }
        if (options.update) {
            writePngMakingFolder(referencePath, actual, 9);  // references are committed: the smallest files
            c.updated = true;
        }
    }
    c.seconds += secondsSince(start);
}

// Renders the scenes on one context, each render's comparison handed to a worker thread while the
// next scene renders. The frames waiting for their comparison count against the memory budget of the
// scene being drawn: at most as many as the machine has cores, of at most that scene's size each (a
// small scene after a large one waits for the large one's comparison), so one large scene does not
// make every small one too large for the budget.
void renderAndCompare(TestRun& run, std::vector<Scene>& scenes, const std::vector<std::size_t>& caseOfScene,
                      const Options& options, const ShaderLibrary& shaders, HeadlessBackend backend, int msaaSamples) {
    const std::size_t workers = std::max(1u, std::thread::hardware_concurrency());
    const auto frameBytes = [](const Scene& s) { return 4 * std::uint64_t(s.width) * std::uint64_t(s.height); };
    const auto keptWhileDrawing = [&](std::size_t i) { return workers * frameBytes(scenes[i]); };
    struct Pending {
        std::future<void> done;
        std::uint64_t bytes;
    };
    std::deque<Pending> pending;
    std::uint64_t pendingBytes = 0;
    const auto waitForOldest = [&] {
        pending.front().done.get();
        pendingBytes -= pending.front().bytes;
        pending.pop_front();
    };
    auto last = Clock::now();
    const auto rendered = [&](std::size_t i, Image image) {
        TestCase& c = run.cases[caseOfScene[i]];
        c.seconds = secondsSince(last);
        const std::uint64_t bytes = image.rgba.size();
        pending.push_back({std::async(std::launch::async,
                                      [&c, &options, image = std::move(image)] { compareCase(c, image, options); }),
                           bytes});
        pendingBytes += bytes;
        // Before the next scene is drawn: what waits fits what its budget check counted.
        const std::uint64_t room = i + 1 < scenes.size() ? keptWhileDrawing(i + 1) : ~std::uint64_t(0);
        while (!pending.empty() && (pending.size() > workers || pendingBytes > room)) waitForOldest();
        last = Clock::now();
    };
    const auto failed = [&](std::size_t i, const std::exception& e) {
        TestCase& c = run.cases[caseOfScene[i]];
        c.seconds = secondsSince(last);
        last = Clock::now();
        c.shaderError = dynamic_cast<const ShaderError*>(&e) != nullptr;
        c.message = c.shaderError ? joinedLines(e.what()) : std::string(e.what());
    };
    try {
        renderScenesHeadless(scenes, shaders, backend, rendered, msaaSamples, keptWhileDrawing, failed);
    } catch (...) {
        for (Pending& p : pending) p.done.wait();  // they refer to `run`
        throw;
    }
    while (!pending.empty()) waitForOldest();
}

void writeText(const std::string& path, const std::string& text) {
    writeFileAtomic(path, [&text](std::FILE* f) { return std::fwrite(text.data(), 1, text.size(), f) == text.size(); });
}

void writeReports(const TestRun& run, const Options& options) {
    for (const auto& [file, text] : {std::pair{options.junit, &junitXml}, std::pair{options.report, &htmlReport}}) {
        if (!file) continue;
        writeText(*file, text(run));
        if (options.verbose) std::cerr << "shadelab: wrote " << *file << "\n";
    }
}

}  // namespace

int runTestSuite(const Options& options, const ShaderLibrary& shaders, HeadlessBackend backend, int msaaSamples) {
    const auto start = Clock::now();
    TestRun run;
    run.dir = *options.testDir;
    run.referencesDir = options.referencesDir.value_or(run.dir);
    run.shaderDir = options.shaderDir;
    if (options.shard) run.shard = std::to_string(options.shard->first) + "/" + std::to_string(options.shard->second);
    run.tolerance = referenceTolerance(options);
    std::vector<std::string> names;
    for (const std::string& file : sceneFiles(run.dir)) names.push_back(withoutExtension(file, 5));
    const std::vector<std::string> picked = selectedNames(names, options);
    if (options.list) {
        for (const std::string& name : picked) std::cout << name << "\n";
        return 0;
    }
    std::error_code ec;
    if (options.referencesDir && !fs::is_directory(run.referencesDir, ec)) {
        // --update makes a new folder of references; without, a missing one is a mistyped name.
        if (!options.update)
            throw InputError("--references: " + run.referencesDir + ": no such folder (--update creates it)");
        if (!fs::create_directories(run.referencesDir, ec) && ec)
            throw InputError("--references: " + run.referencesDir + ": cannot create the folder: " + ec.message());
    }
    if (options.artifacts && !fs::is_directory(*options.artifacts, ec) &&
        !fs::create_directories(*options.artifacts, ec) && ec)
        throw InputError("--artifacts: " + *options.artifacts + ": cannot create the folder: " + ec.message());
    warnAboutOrphans(run, names, options);
    std::vector<Scene> scenes;
    std::vector<std::size_t> caseOfScene;
    run.cases = loadCases(run, picked, options, scenes, caseOfScene);
    try {
        renderAndCompare(run, scenes, caseOfScene, options, shaders, backend, msaaSamples);
    } catch (const GlUnavailable& e) {
        // Not a failing case but a run that cannot start: exit status 2, one line, and the reports say why.
        run.runError = e.what();
        run.cases.clear();  // none was run
        run.seconds = secondsSince(start);
        writeReports(run, options);
        throw InputError("--test " + run.dir + ": OpenGL cannot start: " + run.runError);
    }
    run.seconds = secondsSince(start);

    bool allWell = true;  // every case matches, or had its reference rewritten
    for (const TestCase& c : run.cases) {
        if (c.outcome == CaseOutcome::Match) continue;
        std::cout << caseLine(run, c) << "\n";
        if (c.updated)
            std::cout << oneLine("shadelab: --test " + run.dir + ": " + c.name + ": --update: wrote " +
                                 c.referencePath + " from this render")
                      << "\n";
        allWell = allWell && c.updated;
    }
    writeReports(run, options);
    std::cout << summaryLine(run) << std::endl;
    return allWell ? 0 : 1;
}

}  // namespace shadelab
