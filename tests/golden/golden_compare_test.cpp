// The golden-image comparisons and the manifest (framework/render/golden.h), on hand-made images:
// no GL, no student code.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "render/golden.h"

namespace a6::golden {
namespace {

namespace fs = std::filesystem;

const Rgba kWhite{255, 255, 255, 255}, kBlack{0, 0, 0, 255};

// A fresh folder under the current one (ctest runs this test in its build folder): not a fixed
// name in /tmp, which another user's run (root's, or another student's) would own.
std::string scratch(const std::string& name) {
  const fs::path dir = fs::current_path() / "golden_compare_scratch" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

GoldenImage imageOf(std::vector<std::string> baselines, int w = 64, int h = 64) {
  GoldenImage g;
  g.name = "sample";
  g.scene = "cloth_shear";
  g.width = w;
  g.height = h;
  g.task = 4;
  g.tasks = {1, 2, 3, 4};
  g.tolerance = {16, 0.01, 16};
  g.baselines = std::move(baselines);
  return g;
}

// A white image with a black square of side `side` at (x, y).
Image square(int x, int y, int side, int w = 64, int h = 64) {
  Image image(w, h, kWhite);
  image.fillRect(x, y, side, side, kBlack);
  return image;
}

void write(const Image& image, const std::string& folder, const std::string& file) {
  ASSERT_EQ(writePng(image, folder + "/" + file), "");
}

TEST(GoldenCompare, IdenticalPixelsPassExactly) {
  const std::string dir = scratch("exact");
  write(square(10, 10, 8), dir, "a.png");
  const Verdict v = compareWithBaselines(square(10, 10, 8), imageOf({"a.png"}), dir);
  EXPECT_TRUE(v.passed);
  EXPECT_TRUE(v.identical);
  EXPECT_EQ(v.matched, 0);
}

TEST(GoldenCompare, TheToleranceCountsPixelsOverThePerChannelDifference) {
  const std::string dir = scratch("tolerance");
  write(square(10, 10, 8), dir, "a.png");
  // 8 pixels of 4096 moved (0.2 %): within 1 %.
  Verdict v = compareWithBaselines(square(11, 10, 8), imageOf({"a.png"}), dir);
  EXPECT_TRUE(v.passed);
  EXPECT_FALSE(v.identical);
  EXPECT_NEAR(v.checks[0].result.fractionOverTolerance, 16.0 / 4096, 1e-12);
  // A square elsewhere: 128 pixels (3 %) over.
  v = compareWithBaselines(square(40, 40, 8), imageOf({"a.png"}), dir);
  EXPECT_FALSE(v.passed);
  // Colour noise below perChannel does not count.
  Image noisy = square(10, 10, 8);
  for (int x = 0; x < 64; ++x) noisy.set(x, 0, Rgba{240, 240, 240, 255});
  v = compareWithBaselines(noisy, imageOf({"a.png"}), dir);
  EXPECT_TRUE(v.passed);
  EXPECT_EQ(v.checks[0].result.pixelsOverTolerance, 0);
}

TEST(GoldenCompare, AnyApprovedBaselinePasses) {
  const std::string dir = scratch("baselines");
  write(square(10, 10, 8), dir, "a.png");
  write(square(40, 40, 8), dir, "a.variant.png");
  const Verdict v =
      compareWithBaselines(square(40, 40, 8), imageOf({"a.png", "a.variant.png"}), dir);
  EXPECT_TRUE(v.passed);
  EXPECT_EQ(v.matched, 1);
  EXPECT_FALSE(v.checks[0].passed);
  EXPECT_TRUE(v.checks[1].passed);
  EXPECT_EQ(v.expected.at(44, 44), kBlack) << "the matched baseline is the one shown";
}

TEST(GoldenCompare, AMissingOrMisSizedBaselineIsReportedNotFatal) {
  const std::string dir = scratch("missing");
  write(square(10, 10, 8, 32, 32), dir, "small.png");
  write(square(10, 10, 8), dir, "a.png");
  const Verdict v =
      compareWithBaselines(square(10, 10, 8), imageOf({"gone.png", "small.png", "a.png"}), dir);
  EXPECT_TRUE(v.passed);
  EXPECT_EQ(v.matched, 2);
  EXPECT_NE(v.checks[0].error, "");
  EXPECT_NE(v.checks[1].error.find("32x32"), std::string::npos) << v.checks[1].error;
  EXPECT_NE(describeChecks(imageOf({"gone.png", "small.png", "a.png"}), v).find("gone.png"),
            std::string::npos);
}

TEST(GoldenCompare, DensityForgivesMovedDotsButNotAMovedCrowd) {
  const std::string dir = scratch("density");
  // 16 dots of 5x5 in the left half; the same dots shifted by 3 px; then all in the right half.
  auto dots = [](int dx, int offset) {
    Image image(64, 64, kWhite);
    for (int k = 0; k < 16; ++k) {
      image.fillRect(offset + (k % 4) * 6 + dx, 4 + (k / 4) * 14, 5, 5, kBlack);
    }
    return image;
  };
  write(dots(0, 2), dir, "a.png");
  GoldenImage g = imageOf({"a.png"});
  g.compare = CompareMode::Density;
  g.tolerance = {32, 0.0, 32};
  EXPECT_FALSE(compareWithBaselines(dots(3, 2), imageOf({"a.png"}), dir).passed)
      << "pixel mode sees every moved dot";
  EXPECT_TRUE(compareWithBaselines(dots(3, 2), g, dir).passed) << "density mode does not";
  EXPECT_FALSE(compareWithBaselines(dots(0, 36), g, dir).passed) << "a crowd moved elsewhere";
}

TEST(GoldenCompare, BlockAverageRoundsAndKeepsPartialBlocks) {
  Image image(3, 2, kWhite);
  image.set(0, 0, kBlack);
  const Image blocks = blockAverage(image, 2);
  ASSERT_EQ(blocks.width, 2);
  ASSERT_EQ(blocks.height, 1);
  EXPECT_EQ(blocks.at(0, 0).r, 191);  // (0 + 3 x 255) / 4 = 191.25
  EXPECT_EQ(blocks.at(1, 0).r, 255);  // the partial block: 2 white pixels
}

TEST(GoldenCompare, FailureImagesAreWrittenAndRemoved) {
  const std::string dir = scratch("failures");
  const GoldenImage g = imageOf({"a.png"});
  const FailureFiles files = writeFailureImages(g, square(1, 1, 4), square(9, 9, 4), dir + "/out");
  ASSERT_EQ(files.error, "");
  for (const std::string& file : {files.actual, files.expected, files.difference}) {
    EXPECT_TRUE(fs::exists(file)) << file;
  }
  const ImageResult diff = readPng(files.difference);
  ASSERT_TRUE(diff) << diff.error;
  EXPECT_EQ(diff.image.at(30, 30), (Rgba{0, 0, 0, 255})) << "identical pixels are black";
  EXPECT_NE(diff.image.at(2, 2), (Rgba{0, 0, 0, 255}));
  removeFailureImages(g, dir + "/out");
  EXPECT_FALSE(fs::exists(files.actual));
}

TEST(GoldenManifest, RoundTripsAndNamesTheBadEntry) {
  const std::string dir = scratch("manifest");
  Manifest m;
  GoldenImage g = imageOf({"a.png", "a.variant.png"});
  g.compare = CompareMode::Density;
  g.tolerance = {32, 0.02, 48};
  g.frame = 60;
  g.time = 1.0;
  g.shows = "a picture";
  g.hint = "check something";
  m.images = {g};
  ASSERT_EQ(writeManifest(m, dir + "/manifest.json"), "");
  const ManifestResult read = readManifest(dir + "/manifest.json");
  ASSERT_TRUE(read) << read.error;
  ASSERT_EQ(read.manifest.images.size(), 1u);
  const GoldenImage& r = read.manifest.images[0];
  EXPECT_EQ(r.name, g.name);
  EXPECT_EQ(r.compare, CompareMode::Density);
  EXPECT_EQ(r.tolerance.block, 48);
  EXPECT_EQ(r.tasks, g.tasks);
  EXPECT_EQ(r.baselines, g.baselines);
  EXPECT_EQ(read.manifest.folder, dir);
  EXPECT_EQ(describeTasks(r),
            "task 4 (cloth.cpp), on top of task 1 (spring.cpp), task 2 (forces.cpp), task 3 "
            "(time_stepping.cpp)");

  // A bad entry: the error names the file and the image.
  std::ofstream(dir + "/bad.json")
      << R"({"format": "a6-golden-manifest", "version": 1, "images": [{"name": "x",
             "scene": "s", "frame": 0, "width": 0, "height": 8, "tolerance": {"perChannel": 0,
             "maxFraction": 0}, "task": 1, "tasks": [1], "baselines": ["x.png"]}]})";
  const ManifestResult bad = readManifest(dir + "/bad.json");
  EXPECT_FALSE(bad);
  EXPECT_NE(bad.error.find("bad.json: image 0 (x): width and height"), std::string::npos)
      << bad.error;
  EXPECT_FALSE(readManifest(dir + "/none.json"));
}

}  // namespace
}  // namespace a6::golden
