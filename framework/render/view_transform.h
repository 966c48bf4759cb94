// From the world (metres, y up) to an image (pixels, y down) and back, for a Snapshot's View.
//
// The view shows view.height metres from the bottom of the image to the top, centred on
// view.center; the width follows the image's aspect ratio (width_m = height_m * w / h), so a
// circle stays round at any size. Pixel (i, j) covers [i, i+1) x [j, j+1) from the top-left
// corner; its centre is (i + 0.5, j + 0.5).
#pragma once

#include "scenes/snapshot.h"

namespace a6 {

struct ViewTransform {
  View view;
  int width = 1, height = 1;  ///< image size, pixels

  ViewTransform(const View& v, int w, int h) : view(v), width(w), height(h) {}

  /// Metres per pixel (the same along x and y).
  double metersPerPixel() const { return view.height / height; }
  /// The world width shown, m.
  double worldWidth() const { return view.height * width / height; }

  /// World point -> continuous pixel coordinates (x right, y down, origin top-left).
  Vec2 toPixel(const Vec2& world) const {
    const double s = 1.0 / metersPerPixel();
    return Vec2(0.5 * width + (world.x() - view.center.x()) * s,
                0.5 * height - (world.y() - view.center.y()) * s);
  }
  /// Continuous pixel coordinates -> world point (the inverse of toPixel).
  Vec2 toWorld(const Vec2& pixel) const {
    const double m = metersPerPixel();
    return Vec2(view.center.x() + (pixel.x() - 0.5 * width) * m,
                view.center.y() - (pixel.y() - 0.5 * height) * m);
  }
  /// World point -> OpenGL normalized device coordinates ([-1, 1]², y up).
  Vec2 toNdc(const Vec2& world) const {
    return Vec2(2.0 * (world.x() - view.center.x()) / worldWidth(),
                2.0 * (world.y() - view.center.y()) / view.height);
  }
};

}  // namespace a6
