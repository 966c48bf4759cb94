// WRONG VERSION (task 1): no guard for coincident particles: l = 0 makes e = d / l NaN, and the
// NaN force spreads to every particle of a cloth in one step. Every other spring is right.
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e - kd * vRel * e;
}

}  // namespace a6
