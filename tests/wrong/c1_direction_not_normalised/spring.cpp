// WRONG VERSION (task 1, written blind from the handout): The direction e is taken as d = x2 - x1
// without dividing by l, so the elastic term is scaled by an extra factor l and the damping term by
// l².
// Task 1 — Spring::computeForce
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d;  // direction
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e - kd * vRel * e;
}

}  // namespace a6
