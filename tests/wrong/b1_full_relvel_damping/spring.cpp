// WRONG VERSION (task 1, written blind from the handout): Damping uses the full relative velocity
// -kd (v2 - v1) instead of its component along the spring -kd ((v2 - v1)·e) e, so sideways relative
// motion is damped too.
// Task 1 — Spring::computeForce
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e - kd * (p2->v - p1->v);
}

}  // namespace a6
