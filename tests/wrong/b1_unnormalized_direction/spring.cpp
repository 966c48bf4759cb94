// WRONG VERSION (task 1, written blind from the handout): The elastic term uses the unnormalised
// vector d instead of the unit vector e, i.e. f2 = -ks (l - l0) d - kd v_rel e, so the spring force
// is scaled by an extra factor l.
// Task 1 — Spring::computeForce
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * d - kd * vRel * e;
}

}  // namespace a6
