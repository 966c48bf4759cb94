// Task 1 — Spring::computeForce (slides "Spring forces", "Spring implementation").
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  // Direction and length of the spring: d = x2 - x1, l = |d|.
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();  // coincident particles: no direction, no force
  const Vec2 e = d / l;

  // Relative velocity along the spring: v_rel = (v2 - v1)·e.
  const double vRel = (p2->v - p1->v).dot(e);

  // f2 = -ks (l - l0) e - kd v_rel e; p1 gets -f2.
  return -ks * (l - restLength) * e - kd * vRel * e;
}

}  // namespace a6
