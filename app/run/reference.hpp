#pragma once
// --reference REF.png: the --output image (a frame or a plot) compared with a reference, for screenshot
// tests in a user's CI. Exit status 0 when they match, 1 when they differ (or their sizes do), 2 when
// the reference is missing or not a PNG; one line on stdout says which, with the numbers. GL-free: the
// run modes (main.cpp's plot, run_headless.cpp's frame) call it around their render.
#include "core/image/image.hpp"
#include "options/options.hpp"

#include <optional>
#include <string>

namespace shadelab {

// Before rendering: the reference, read; none when there is no --reference, or when it is missing and
// --reference-missing=write will create it. Throws InputError (exit 2, nothing written) for a missing
// reference (otherwise), one that is not a PNG or cannot be read, or a --reference or --diff-output
// that names the --output file.
std::optional<Image> readReference(const Options& options);

// After rendering: writes `image` to --output (in every case, atomically), then compares it with
// `reference` (or writes the reference from it when --reference-missing=write found none), writes
// --diff-output with the diff layout's `diffFactor`, and prints the line. Returns the exit status.
int writeOutputAndCompare(const Options& options, const Image& image, const std::optional<Image>& reference,
                          float diffFactor);

// The thresholds: --max-diff and --mean-diff, or the defaults.
ImageTolerance referenceTolerance(const Options& options);

// "160x120".
std::string sizeText(const Image& image);

}  // namespace shadelab
