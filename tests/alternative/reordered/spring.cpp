// Alternative (correct) task 1: the same spring force by another algebra. Instead of the unit
// vector e = d / l, it scales d itself once at the end:
//   f2 = -(ks (l - l0) + kd (v2 - v1)·d / l) / l · d
// which equals -ks (l - l0) e - kd v_rel e to round-off.
#include "a6/spring.h"

#include <cmath>

namespace a6 {

Vec2 Spring::computeForce() const {
  const Vec2 d = p2->x - p1->x;
  const double l = std::sqrt(d.x() * d.x() + d.y() * d.y());
  if (!(l >= 1e-12)) return Vec2::Zero();  // coincident particles: no direction, no force

  const Vec2 dv = p2->v - p1->v;
  const double along = ks * (l - restLength) + kd * (dv.dot(d) / l);  // N, along e
  return d * (-along / l);
}

}  // namespace a6
