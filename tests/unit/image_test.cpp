#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/image/image.hpp"
#include "test_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

using namespace shadelab;
namespace fs = std::filesystem;

namespace {
Image gradient(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = img.pixel(x, y);
            p[0] = std::uint8_t(x * 4), p[1] = std::uint8_t(y * 4), p[2] = 128, p[3] = 255;
        }
    return img;
}
struct TempDir : test::TestDir {
    TempDir() : TestDir("image") {}
};
}  // namespace

TEST(Image, PngRoundTrip) {
    TempDir dir;
    const Image img = gradient(40, 30);
    const std::string file = (dir.path / "g.png").string();
    writePng(file, img);
    const Image back = readPng(file);
    EXPECT_EQ(back.width, 40);
    EXPECT_EQ(back.height, 30);
    EXPECT_EQ(back.rgba, img.rgba);
    // Nothing but the image is left in the folder: the temporary was renamed.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 1);
}

TEST(Image, FailedWriteLeavesNoFileAndKeepsTheOldOne) {
    TempDir dir;
    const std::string file = (dir.path / "keep.png").string();
    writePng(file, gradient(4, 4));
    EXPECT_THROW(writeFileAtomic(file, [](std::FILE* f) { std::fputs("partial", f); return false; }), InputError);
    EXPECT_THROW(writeFileAtomic(file, [](std::FILE*) -> bool { throw std::runtime_error("killed"); }),
                 std::runtime_error);
    EXPECT_EQ(readPng(file).width, 4);  // the previous image is intact
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 1);
    EXPECT_THROW(writePng((dir.path / "missing" / "x.png").string(), gradient(2, 2)), InputError);
}

TEST(Image, ReadingANonPngNamesTheFile) {
    TempDir dir;
    const std::string file = (dir.path / "not.png").string();
    writeFileAtomic(file, [](std::FILE* f) { return std::fputs("hello", f) >= 0; });
    try {
        readPng(file);
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("not.png"), std::string::npos);
    }
}

TEST(Image, CompareCountsPixelsOverTheThreshold) {
    const Image a = gradient(10, 10);
    Image b = a;
    b.pixel(3, 3)[0] = std::uint8_t(b.pixel(3, 3)[0] + 20);  // one pixel far off
    b.pixel(4, 4)[1] = std::uint8_t(b.pixel(4, 4)[1] + 2);   // one pixel slightly off
    const CompareResult r = compareImages(b, a, 8);
    EXPECT_TRUE(r.sizeMatches);
    EXPECT_EQ(r.maxDiff, 20);
    EXPECT_EQ(r.differingPixels, 1u);
    EXPECT_NEAR(r.meanDiff, 22.0 / 400.0, 1e-9);  // 100 pixels x 4 channels
    // The golden tests' kind: a share of the pixels may be over the threshold, by any amount.
    const ImageTolerance none = toleranceWithShare(10, 10, 8, 0.001, 0.5), two = toleranceWithShare(10, 10, 8, 0.02, 0.5);
    EXPECT_EQ(none.maxDiffPixels, 0u);
    EXPECT_EQ(two.maxDiffPixels, 2u);
    EXPECT_FALSE(none.matches(r));
    EXPECT_TRUE(two.matches(r));
    EXPECT_FALSE(toleranceWithShare(10, 10, 8, 0.02, 0.05).matches(r));  // the mean over its limit
    EXPECT_EQ(describe(r, two), "max 20/255 (limit 255), mean 0.055 (limit 0.5), 1 pixel differs by more than 8/255 (limit 2)");
    // A result counted with another threshold cannot be judged by it.
    EXPECT_THROW((void)two.matches(compareImages(b, a, 0)), std::logic_error);
    EXPECT_FALSE(compareImages(gradient(10, 9), a, 8).sizeMatches);
    const Image diff = differenceImage(b, a, 8);
    EXPECT_EQ(diff.pixel(3, 3)[0], 255);
    EXPECT_EQ(diff.pixel(3, 3)[1], 0);
}

TEST(FileIo, OutputPathChecks) {
    TempDir dir;
    EXPECT_THROW(checkOutputPath(dir.path.string(), "--output"), InputError);
    EXPECT_THROW(checkOutputPath((dir.path / "no" / "x.png").string(), "--output"), InputError);
    EXPECT_NO_THROW(checkOutputPath((dir.path / "x.png").string(), "--output"));
    EXPECT_TRUE(hasExtension("A.PNG", ".png"));
    EXPECT_TRUE(hasModelExtension("m.GlB"));
    EXPECT_FALSE(hasModelExtension("m.json"));
}

// --playlist --output DIR/: an existing folder, or a new one named with a trailing '/' inside an
// existing folder; never a file, never a tree of missing folders.
TEST(FileIo, OutputFolderChecks) {
    TempDir dir;
    const std::string existing = dir.path.string();
    EXPECT_NO_THROW(checkOutputFolder(existing, "--output"));
    EXPECT_NO_THROW(checkOutputFolder(existing + "/", "--output"));
    writePng((dir.path / "x.png").string(), gradient(2, 2));
    auto message = [](const std::string& path) {
        try {
            checkOutputFolder(path, "--output");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message((dir.path / "x.png").string()).find("--output: "), std::string::npos);
    EXPECT_NE(message((dir.path / "x.png").string()).find("is a file"), std::string::npos);
    EXPECT_NE(message((dir.path / "new").string()).find("end the name with /"), std::string::npos);
    EXPECT_NE(message((dir.path / "no" / "new/").string()).find("does not exist"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir.path / "new"));
    EXPECT_FALSE(fs::exists(dir.path / "no"));

    createOutputFolder((dir.path / "new/").string(), "--output");
    EXPECT_TRUE(fs::is_directory(dir.path / "new"));
    EXPECT_NO_THROW(createOutputFolder((dir.path / "new/").string(), "--output"));  // already there: fine
    EXPECT_THROW(createOutputFolder((dir.path / "no" / "new/").string(), "--output"), InputError);
    EXPECT_FALSE(fs::exists(dir.path / "no"));
}

// Issue 19: --reference's numbers, per channel as magnum's CompareImage: the largest difference of any
// channel (alpha too) and the mean over every channel of every pixel.
TEST(Image, ChannelDifferences) {
    Image a(4, 2), b(4, 2);
    for (std::size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] = b.rgba[i] = 100;
    CompareResult r = compareImages(a, b, 0);
    EXPECT_TRUE(r.sizeMatches);
    EXPECT_EQ(r.maxDiff, 0);
    EXPECT_EQ(r.meanDiff, 0.0);
    b.pixel(1, 0)[0] = 103;  // 3 in red
    b.pixel(2, 1)[2] = 95;   // 5 in blue
    b.pixel(3, 1)[3] = 98;   // 2 in alpha
    r = compareImages(a, b, 0);
    EXPECT_EQ(r.maxDiff, 5);
    EXPECT_DOUBLE_EQ(r.meanDiff, (3.0 + 5.0 + 2.0) / 32.0);  // 8 pixels x 4 channels

    const ImageTolerance t{5, 10.0 / 32.0, std::nullopt};
    EXPECT_TRUE(t.matches(r));
    EXPECT_FALSE((ImageTolerance{4, 1.0, std::nullopt}).matches(r));          // the max over its limit
    EXPECT_FALSE((ImageTolerance{255, 9.9 / 32.0, std::nullopt}).matches(r));  // the mean over its limit
    // Issue 32: the pixels that differ at all, in any channel (alpha too): three.
    EXPECT_EQ(r.differingPixels, 3u);
    EXPECT_TRUE((ImageTolerance{5, 1.0, 3}).matches(r));
    EXPECT_FALSE((ImageTolerance{5, 1.0, 2}).matches(r));  // more pixels than allowed
    EXPECT_FALSE(t.matches(compareImages(a, Image(4, 3), 0)));      // another size never matches
    EXPECT_FALSE(compareImages(a, Image(2, 4), 0).sizeMatches);
}

// Issue 19: --diff-output is the diff layout's pane on the CPU (shaders/difference.frag): per channel
// |a - b| x factor, rounded and clamped to 255, alpha 255, whichever image is brighter.
TEST(Image, AmplifiedDifferenceIsTheDiffPane) {
    Image a(3, 1), b(3, 1);
    const std::uint8_t pa[3][4] = {{10, 20, 30, 255}, {200, 0, 255, 255}, {7, 7, 7, 0}};
    const std::uint8_t pb[3][4] = {{10, 21, 27, 255}, {100, 70, 250, 255}, {7, 7, 7, 255}};
    for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 4; ++c) a.pixel(x, 0)[c] = pa[x][c], b.pixel(x, 0)[c] = pb[x][c];
    const Image d = amplifiedDifference(a, b, 4.0f);
    ASSERT_EQ(d.width, 3);
    const std::uint8_t expected[3][4] = {{0, 4, 12, 255}, {255, 255, 20, 255}, {0, 0, 0, 255}};
    for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(d.pixel(x, 0)[c], expected[x][c]) << x << "," << c;
    EXPECT_EQ(amplifiedDifference(b, a, 4.0f).rgba, d.rgba);                // symmetric
    EXPECT_EQ(amplifiedDifference(a, b, 2.5f).pixel(0, 0)[2], 8);           // 3 x 2.5 = 7.5, rounded up
    EXPECT_EQ(amplifiedDifference(a, a, 1000.0f).pixel(1, 0)[0], 0);       // equal is black at any factor
    EXPECT_THROW(amplifiedDifference(a, Image(3, 2), 4.0f), std::invalid_argument);
}
