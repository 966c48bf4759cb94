// WRONG VERSION (task 1): damping on the full relative velocity, -kd (v2 - v1), instead of its
// projection on the spring, -kd ((v2 - v1)·e) e: sideways motion is damped too.
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  return -ks * (l - restLength) * e - kd * (p2->v - p1->v);
}

}  // namespace a6
