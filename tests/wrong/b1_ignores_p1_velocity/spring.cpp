// WRONG VERSION (task 1, written blind from the handout): v_rel is computed from p2's velocity only
// (v2·e) instead of the relative velocity (v2 - v1)·e, so p1's motion is ignored by the damping.
// Task 1 — Spring::computeForce
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = p2->v.dot(e);
  return -ks * (l - restLength) * e - kd * vRel * e;
}

}  // namespace a6
