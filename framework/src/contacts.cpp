#include <cmath>

#include "a6/forces.h"

namespace a6 {

Contact contactWith(const HalfPlane& plane, const Vec2& x) {
  return Contact{plane.offset - plane.normal.dot(x), plane.normal};
}

Contact contactWith(const CircleObstacle& circle, const Vec2& x) {
  const Vec2 d = x - circle.center;
  const double distance = d.norm();
  // At the very centre any direction is as good as another: push up.
  const Vec2 normal = distance > 1e-12 ? Vec2(d / distance) : Vec2(0, 1);
  return Contact{circle.radius - distance, normal};
}

}  // namespace a6
