// WRONG VERSION (task 1, written blind from the handout): The damping speed is v2·e instead of (v2
// - v1)·e: p1's velocity is left out of the relative velocity.
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
