// Images as plain data, PNG files, and the comparisons the golden-image checks make.
//
// Pixels are RGBA, 8 bits per channel, rows from the top of the picture to the bottom (as PNG
// stores them; the renderer flips OpenGL's bottom-up rows before handing an image out).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace a6 {

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba& x, const Rgba& y) {
    return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a;
  }
  friend bool operator!=(const Rgba& x, const Rgba& y) { return !(x == y); }
};

struct Image {
  int width = 0, height = 0;         ///< pixels
  std::vector<std::uint8_t> pixels;  ///< RGBA8, width*height*4 bytes, top row first

  Image() = default;
  /// A width x height image filled with `fill`.
  Image(int width, int height, Rgba fill = Rgba{});

  bool empty() const { return width <= 0 || height <= 0; }
  /// The pixel in column x (from the left) and row y (from the top); no bounds check.
  Rgba at(int x, int y) const;
  void set(int x, int y, Rgba color);
  /// Fills the rectangle [x, x+w) x [y, y+h), clipped to the image.
  void fillRect(int x, int y, int w, int h, Rgba color);
  /// Copies `source` with its top-left corner at (x, y), clipped to this image.
  void blit(const Image& source, int x, int y);
};

/// Writes `image` as an RGBA PNG. Returns an empty string on success, else what went wrong.
[[nodiscard]] std::string writePng(const Image& image, const std::string& path);

/// An image read from a file, or why there is none.
struct ImageResult {
  Image image;
  std::string error;  ///< empty on success
  explicit operator bool() const { return error.empty(); }
};

/// Reads a PNG (any bit depth or colour type; converted to RGBA8). With expectedWidth and
/// expectedHeight > 0, an image of another size is an error too (e.g. a golden rendered at a
/// resolution the manifest does not say).
ImageResult readPng(const std::string& path, int expectedWidth = 0, int expectedHeight = 0);

/// How far `actual` is from `expected`.
struct ImageComparison {
  bool sizesMatch = false;
  bool identical = false;                ///< same size and every decoded byte equal
  int maxChannelDiff = 0;                ///< largest |actual - expected| over all channels, 0..255
  std::int64_t pixelsOverTolerance = 0;  ///< pixels with some channel differing by > tolerance
  double fractionOverTolerance = 0;      ///< pixelsOverTolerance / pixel count, 0..1
  /// Passes a tolerance check: same size and at most maxFraction of pixels over tolerance.
  bool within(double maxFraction) const {
    return sizesMatch && fractionOverTolerance <= maxFraction;
  }
};

/// Compares decoded pixels, alpha included. Different sizes: sizesMatch false, identical false,
/// maxChannelDiff 255, fraction 1.
ImageComparison compare(const Image& actual, const Image& expected, int perChannelTolerance);

/// |a - b| per channel, times `amplify`, on black (opaque). Any pixel that differs at all gets
/// at least 64 in each channel that differs, so a difference of 1 is still visible; identical
/// pixels are exactly black. Where the sizes differ, the area outside the smaller image is
/// magenta.
Image differenceImage(const Image& a, const Image& b, int amplify = 8);

/// Several images side by side in a grid of `columns` columns (rows follow), separated by a
/// thin dark grey line. Each cell is as large as the largest image; smaller images sit at its
/// top-left. With labels (one per image, may be shorter), each cell gets a caption strip above
/// it written in a built-in 5x7 pixel font (letters, digits and . , : ; - _ / ( ) + = % # ').
///
/// Size: width = columns*cellW + (columns+1)*kContactSheetGap, height = rows*(captionH + cellH)
/// + (rows+1)*kContactSheetGap, with captionH = 0 without labels, kContactSheetCaption with.
Image contactSheet(const std::vector<Image>& images, int columns,
                   const std::vector<std::string>& labels = {});
inline constexpr int kContactSheetGap = 2;       ///< separator width, pixels
inline constexpr int kContactSheetCaption = 18;  ///< caption strip height, pixels

/// Writes `text` (the 5x7 font, scaled by `scale`) with its top-left corner at (x, y).
void drawText(Image& image, int x, int y, const std::string& text, Rgba color, int scale = 1);

}  // namespace a6
