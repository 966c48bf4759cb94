// Images without GL: PNG files, comparisons, difference images, contact sheets.
#include "image/image.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace a6 {
namespace {

std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "a6_render_test_" + name;
}

// A small image with something in every channel.
Image gradient(int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      image.set(x, y,
                Rgba{std::uint8_t(x * 255 / std::max(w - 1, 1)),
                     std::uint8_t(y * 255 / std::max(h - 1, 1)), std::uint8_t((x * y) % 256),
                     std::uint8_t(255 - (x + y) % 7)});
    }
  }
  return image;
}

TEST(Png, RoundTripKeepsEveryByte) {
  const Image image = gradient(37, 23);  // odd sizes: no row padding anywhere
  const std::string path = tempPath("roundtrip.png");
  ASSERT_EQ(writePng(image, path), "");
  const ImageResult read = readPng(path, 37, 23);
  ASSERT_TRUE(read) << read.error;
  EXPECT_EQ(read.image.width, 37);
  EXPECT_EQ(read.image.height, 23);
  EXPECT_TRUE(compare(read.image, image, 0).identical);
  EXPECT_EQ(read.image.pixels, image.pixels);
  std::remove(path.c_str());
}

TEST(Png, TheSameImageGivesTheSameFile) {
  const std::string a = tempPath("same_a.png"), b = tempPath("same_b.png");
  ASSERT_EQ(writePng(gradient(20, 20), a), "");
  ASSERT_EQ(writePng(gradient(20, 20), b), "");
  auto bytes = [](const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(bytes(a), bytes(b));
  std::remove(a.c_str());
  std::remove(b.c_str());
}

TEST(Png, ErrorsSayWhatIsWrong) {
  const ImageResult missing = readPng(tempPath("does_not_exist.png"));
  EXPECT_FALSE(missing);
  EXPECT_NE(missing.error.find("cannot open"), std::string::npos) << missing.error;
  EXPECT_NE(missing.error.find("does_not_exist.png"), std::string::npos) << missing.error;

  const std::string text = tempPath("not_a_png.png");
  std::ofstream(text) << "hello, I am a text file";
  const ImageResult notPng = readPng(text);
  EXPECT_FALSE(notPng);
  EXPECT_NE(notPng.error.find("not a PNG"), std::string::npos) << notPng.error;
  std::remove(text.c_str());

  const std::string path = tempPath("size.png");
  ASSERT_EQ(writePng(gradient(10, 12), path), "");
  const ImageResult wrongSize = readPng(path, 12, 10);
  EXPECT_FALSE(wrongSize);
  EXPECT_NE(wrongSize.error.find("is 10x12, expected 12x10"), std::string::npos) << wrongSize.error;
  std::remove(path.c_str());

  const std::string unwritable = tempPath("no_such_folder/x.png");
  const std::string error = writePng(gradient(4, 4), unwritable);
  EXPECT_NE(error.find("cannot open"), std::string::npos) << error;
  EXPECT_NE(writePng(Image(), tempPath("empty.png")), "") << "an empty image is an error";
}

TEST(Compare, DetectsOneChangedPixelAndReportsTheFraction) {
  const Image expected = gradient(40, 25);
  Image actual = expected;
  EXPECT_TRUE(compare(actual, expected, 0).identical);

  Rgba p = actual.at(7, 3);
  p.g = static_cast<std::uint8_t>(p.g ^ 1);  // off by one in one channel of one pixel
  actual.set(7, 3, p);
  const ImageComparison exact = compare(actual, expected, 0);
  EXPECT_TRUE(exact.sizesMatch);
  EXPECT_FALSE(exact.identical);
  EXPECT_EQ(exact.maxChannelDiff, 1);
  EXPECT_EQ(exact.pixelsOverTolerance, 1);
  EXPECT_DOUBLE_EQ(exact.fractionOverTolerance, 1.0 / (40 * 25));

  const ImageComparison tolerant = compare(actual, expected, 2);
  EXPECT_FALSE(tolerant.identical) << "tolerance never makes different pixels identical";
  EXPECT_EQ(tolerant.pixelsOverTolerance, 0);
  EXPECT_TRUE(tolerant.within(0.0));
}

TEST(Compare, DifferentSizesNeverMatch) {
  const ImageComparison c = compare(gradient(10, 10), gradient(10, 11), 255);
  EXPECT_FALSE(c.sizesMatch);
  EXPECT_FALSE(c.identical);
  EXPECT_EQ(c.maxChannelDiff, 255);
  EXPECT_DOUBLE_EQ(c.fractionOverTolerance, 1.0);
  EXPECT_FALSE(c.within(1.0));
}

TEST(DifferenceImage, IsNonZeroExactlyWhereTheImagesDiffer) {
  const Image a = gradient(30, 20);
  Image b = a;
  b.set(3, 4, Rgba{0, 0, 0, 255});
  b.set(29, 19,
        Rgba{a.at(29, 19).r, a.at(29, 19).g, std::uint8_t(a.at(29, 19).b ^ 1), a.at(29, 19).a});
  const Image diff = differenceImage(a, b, 8);
  ASSERT_EQ(diff.width, 30);
  ASSERT_EQ(diff.height, 20);
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 30; ++x) {
      const Rgba d = diff.at(x, y);
      const bool differs = a.at(x, y) != b.at(x, y);
      EXPECT_EQ(d.r || d.g || d.b, differs) << "pixel " << x << "," << y;
      EXPECT_EQ(d.a, 255);
    }
  }
  // A difference of 1 is still visible.
  EXPECT_GE(diff.at(29, 19).b, 64);
  EXPECT_EQ(diff.at(29, 19).r, 0);
}

TEST(ContactSheet, HasTheDocumentedSize) {
  const std::vector<Image> images = {gradient(30, 20), gradient(25, 22), gradient(10, 10),
                                     gradient(30, 5), gradient(8, 8)};
  const int cellW = 30, cellH = 22, gap = kContactSheetGap;
  const Image plain = contactSheet(images, 2);
  EXPECT_EQ(plain.width, 2 * cellW + 3 * gap);
  EXPECT_EQ(plain.height, 3 * cellH + 4 * gap);
  // The first image sits at (gap, gap), unchanged.
  EXPECT_EQ(plain.at(gap, gap), images[0].at(0, 0));
  EXPECT_EQ(plain.at(gap + 29, gap + 19), images[0].at(29, 19));
  // The second one starts one cell and one gap to the right.
  EXPECT_EQ(plain.at(2 * gap + cellW, gap), images[1].at(0, 0));

  const Image labelled = contactSheet(images, 3, {"actual", "expected", "diff x8"});
  EXPECT_EQ(labelled.width, 3 * cellW + 4 * gap);
  EXPECT_EQ(labelled.height, 2 * (kContactSheetCaption + cellH) + 3 * gap);
  EXPECT_EQ(labelled.at(gap, gap + kContactSheetCaption), images[0].at(0, 0));

  EXPECT_TRUE(contactSheet({}, 3).empty());
}

TEST(Image, FillAndBlitClipToTheImage) {
  Image image(4, 3, Rgba{1, 2, 3, 255});
  image.fillRect(-2, -2, 4, 3, Rgba{9, 9, 9, 255});  // covers (0..1, 0)
  EXPECT_EQ(image.at(1, 0), (Rgba{9, 9, 9, 255}));
  EXPECT_EQ(image.at(2, 0), (Rgba{1, 2, 3, 255}));
  EXPECT_EQ(image.at(0, 1), (Rgba{1, 2, 3, 255}));
  image.blit(Image(10, 10, Rgba{7, 7, 7, 255}), 3, 2);
  EXPECT_EQ(image.at(3, 2), (Rgba{7, 7, 7, 255}));
  EXPECT_EQ(image.at(2, 2), (Rgba{1, 2, 3, 255}));
}

}  // namespace
}  // namespace a6
