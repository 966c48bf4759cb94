#include "image/image.h"

#include <algorithm>
#include <cstdlib>

namespace a6 {

Image::Image(int w, int h, Rgba fill) : width(std::max(w, 0)), height(std::max(h, 0)) {
  pixels.resize(static_cast<size_t>(width) * height * 4);
  for (size_t i = 0; i < pixels.size(); i += 4) {
    pixels[i] = fill.r, pixels[i + 1] = fill.g, pixels[i + 2] = fill.b, pixels[i + 3] = fill.a;
  }
}

Rgba Image::at(int x, int y) const {
  const std::uint8_t* p = &pixels[(static_cast<size_t>(y) * width + x) * 4];
  return Rgba{p[0], p[1], p[2], p[3]};
}

void Image::set(int x, int y, Rgba c) {
  std::uint8_t* p = &pixels[(static_cast<size_t>(y) * width + x) * 4];
  p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = c.a;
}

void Image::fillRect(int x, int y, int w, int h, Rgba color) {
  const int x0 = std::max(x, 0), x1 = std::min(x + w, width);
  const int y0 = std::max(y, 0), y1 = std::min(y + h, height);
  for (int row = y0; row < y1; ++row) {
    for (int col = x0; col < x1; ++col) set(col, row, color);
  }
}

void Image::blit(const Image& source, int x, int y) {
  const int x0 = std::max(x, 0), x1 = std::min(x + source.width, width);
  const int y0 = std::max(y, 0), y1 = std::min(y + source.height, height);
  for (int row = y0; row < y1; ++row) {
    for (int col = x0; col < x1; ++col) set(col, row, source.at(col - x, row - y));
  }
}

ImageComparison compare(const Image& actual, const Image& expected, int tolerance) {
  ImageComparison result;
  result.sizesMatch = actual.width == expected.width && actual.height == expected.height &&
                      actual.pixels.size() == expected.pixels.size();
  if (!result.sizesMatch) {
    result.maxChannelDiff = 255;
    result.fractionOverTolerance = 1;
    result.pixelsOverTolerance = std::max<std::int64_t>(
        std::int64_t(actual.width) * actual.height, std::int64_t(expected.width) * expected.height);
    return result;
  }
  const size_t count = actual.pixels.size() / 4;
  for (size_t i = 0; i < count; ++i) {
    int worst = 0;
    for (size_t c = 0; c < 4; ++c) {
      worst = std::max(worst,
                       std::abs(int(actual.pixels[4 * i + c]) - int(expected.pixels[4 * i + c])));
    }
    result.maxChannelDiff = std::max(result.maxChannelDiff, worst);
    if (worst > tolerance) ++result.pixelsOverTolerance;
  }
  result.identical = result.maxChannelDiff == 0;
  result.fractionOverTolerance = count ? double(result.pixelsOverTolerance) / double(count) : 0.0;
  return result;
}

Image differenceImage(const Image& a, const Image& b, int amplify) {
  const int w = std::max(a.width, b.width), h = std::max(a.height, b.height);
  Image diff(w, h, Rgba{255, 0, 255, 255});
  const int commonW = std::min(a.width, b.width), commonH = std::min(a.height, b.height);
  for (int y = 0; y < commonH; ++y) {
    for (int x = 0; x < commonW; ++x) {
      const Rgba p = a.at(x, y), q = b.at(x, y);
      const int d[4] = {std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b),
                        std::abs(p.a - q.a)};
      auto channel = [&](int c) -> std::uint8_t {
        if (d[c] == 0 && d[3] == 0) return 0;
        // An alpha difference shows in every colour channel.
        const int v = std::max(d[c], d[3]);
        return static_cast<std::uint8_t>(std::clamp(v * amplify, 64, 255));
      };
      diff.set(x, y, Rgba{channel(0), channel(1), channel(2), 255});
    }
  }
  return diff;
}

// The 5x7 font: 7 rows per glyph, 5 bits per row, leftmost pixel in bit 4.
namespace {

struct Glyph {
  char c;
  std::uint8_t rows[7];
};

constexpr Glyph kFont[] = {
    {'A', {0x0E, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11}},
    {'B', {0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E}},
    {'C', {0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E}},
    {'D', {0x1C, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1C}},
    {'E', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F}},
    {'F', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10}},
    {'G', {0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F}},
    {'H', {0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11}},
    {'I', {0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'J', {0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C}},
    {'K', {0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11}},
    {'L', {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F}},
    {'M', {0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11}},
    {'N', {0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11}},
    {'O', {0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}},
    {'P', {0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10}},
    {'Q', {0x0E, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0D}},
    {'R', {0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11}},
    {'S', {0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E}},
    {'T', {0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04}},
    {'U', {0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}},
    {'V', {0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04}},
    {'W', {0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A}},
    {'X', {0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11}},
    {'Y', {0x11, 0x11, 0x11, 0x0A, 0x04, 0x04, 0x04}},
    {'Z', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F}},
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}},
    {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}},
    {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}},
    {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}},
    {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}},
    {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {' ', {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}},
    {',', {0x00, 0x00, 0x00, 0x00, 0x0C, 0x04, 0x08}},
    {':', {0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00}},
    {';', {0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x04, 0x08}},
    {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}},
    {'_', {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1F}},
    {'/', {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00}},
    {'(', {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02}},
    {')', {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}},
    {'+', {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00}},
    {'=', {0x00, 0x00, 0x1F, 0x00, 0x1F, 0x00, 0x00}},
    {'%', {0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03}},
    {'#', {0x0A, 0x0A, 0x1F, 0x0A, 0x1F, 0x0A, 0x0A}},
    {'\'', {0x0C, 0x04, 0x08, 0x00, 0x00, 0x00, 0x00}},
    {'?', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x00, 0x04}},
};

const Glyph& glyphOf(char c) {
  if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  for (const Glyph& g : kFont) {
    if (g.c == c) return g;
  }
  return kFont[sizeof kFont / sizeof kFont[0] - 1];  // '?'
}

}  // namespace

void drawText(Image& image, int x, int y, const std::string& text, Rgba color, int scale) {
  for (size_t i = 0; i < text.size(); ++i) {
    const Glyph& g = glyphOf(text[i]);
    const int left = x + static_cast<int>(i) * 6 * scale;
    for (int row = 0; row < 7; ++row) {
      for (int col = 0; col < 5; ++col) {
        if (g.rows[row] & (0x10 >> col)) {
          image.fillRect(left + col * scale, y + row * scale, scale, scale, color);
        }
      }
    }
  }
}

Image contactSheet(const std::vector<Image>& images, int columns,
                   const std::vector<std::string>& labels) {
  if (images.empty()) return Image();
  columns = std::clamp(columns, 1, static_cast<int>(images.size()));
  const int count = static_cast<int>(images.size());
  const int rows = (count + columns - 1) / columns;
  int cellW = 0, cellH = 0;
  for (const Image& image : images) {
    cellW = std::max(cellW, image.width);
    cellH = std::max(cellH, image.height);
  }
  const int gap = kContactSheetGap;
  const int captionH = labels.empty() ? 0 : kContactSheetCaption;
  const Rgba kSeparator{64, 64, 64, 255}, kEmpty{128, 128, 128, 255};
  const Rgba kCaption{40, 40, 40, 255}, kText{235, 235, 235, 255};
  Image sheet(columns * cellW + (columns + 1) * gap, rows * (captionH + cellH) + (rows + 1) * gap,
              kSeparator);
  for (int k = 0; k < count; ++k) {
    const int x = gap + (k % columns) * (cellW + gap);
    const int y = gap + (k / columns) * (captionH + cellH + gap);
    if (captionH > 0) {
      sheet.fillRect(x, y, cellW, captionH, kCaption);
      if (k < static_cast<int>(labels.size())) {
        // Scale 2 (14 px glyphs); only what fits in the cell.
        const int fits = std::max(0, (cellW - 4) / 12);
        Image caption(cellW, captionH, kCaption);
        drawText(caption, 3, 2, labels[k].substr(0, fits), kText, 2);
        sheet.blit(caption, x, y);
      }
    }
    sheet.fillRect(x, y + captionH, cellW, cellH, kEmpty);
    sheet.blit(images[k], x, y + captionH);
  }
  return sheet;
}

}  // namespace a6
