#include "run/reference.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/base/message.hpp"
#include "core/scene/scene_limits.hpp"

#include <filesystem>
#include <iostream>

namespace shadelab {
namespace {

namespace fs = std::filesystem;

bool samePath(const std::string& a, const std::string& b) {
    std::error_code ec1, ec2;
    const fs::path pa = fs::weakly_canonical(a, ec1), pb = fs::weakly_canonical(b, ec2);
    return ec1 || ec2 ? a == b : pa == pb;
}

void say(const std::string& line) { std::cout << oneLine("shadelab: " + line) << std::endl; }

}  // namespace

std::string sizeText(const Image& image) { return std::to_string(image.width) + "x" + std::to_string(image.height); }

ImageTolerance referenceTolerance(const Options& options) {
    ImageTolerance t;
    if (options.maxDiff) t.maxDiff = *options.maxDiff;
    if (options.meanDiff) t.meanDiff = *options.meanDiff;
    t.maxDiffPixels = options.maxDiffPixels;
    return t;
}

std::optional<Image> readReference(const Options& options) {
    if (!options.reference) return std::nullopt;
    const std::string& reference = *options.reference;
    if (samePath(reference, *options.output))
        throw InputError("--reference: " + reference + " is the --output file: give the reference another name");
    if (options.diffOutput) {
        checkOutputPath(*options.diffOutput, "--diff-output");
        if (samePath(*options.diffOutput, *options.output) || samePath(*options.diffOutput, reference))
            throw InputError("--diff-output: " + *options.diffOutput + " is the --output or --reference file");
    }
    std::error_code ec;
    if (!fs::exists(reference, ec) && !ec) {  // (a folder that cannot be looked into: readPng says so)
        if (options.referenceMissing != MissingReference::Write)
            throw InputError("--reference: " + reference +
                             " does not exist (--reference-missing=write creates it from this render)");
        checkOutputPath(reference, "--reference");
        return std::nullopt;
    }
    try {
        return readPng(reference);
    } catch (const InputError& e) {
        throw InputError(std::string("--reference: ") + e.what());
    }
}

int writeOutputAndCompare(const Options& options, const Image& image, const std::optional<Image>& reference,
                          float diffFactor) {
    const std::string& output = *options.output;
    writePng(output, image);
    if (!options.reference) return 0;
    const std::string& referencePath = *options.reference;
    if (!reference) {
        writePng(referencePath, image);
        say(output + ": the reference " + referencePath + " did not exist: written from this render");
        return 0;
    }
    const std::string against = output + " against " + referencePath + ": ";
    const CompareResult r = compareImages(image, *reference, 0);
    if (!r.sizeMatches) {
        say(against + "size " + sizeText(image) + ", the reference's " + sizeText(*reference) + ": differs" +
            (options.diffOutput ? " (no --diff-output)" : ""));
        return 1;
    }
    if (options.diffOutput) {
        writePng(*options.diffOutput, amplifiedDifference(image, *reference, diffFactor));
        if (options.verbose) std::cerr << "shadelab: wrote " << *options.diffOutput << "\n";
    }
    const ImageTolerance tolerance = referenceTolerance(options);
    const bool matches = tolerance.matches(r);
    say(against + describe(r, tolerance) + (matches ? ": matches" : ": differs"));
    return matches ? 0 : 1;
}

}  // namespace shadelab
