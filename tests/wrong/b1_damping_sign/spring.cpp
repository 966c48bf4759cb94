// WRONG VERSION (task 1, written blind from the handout): The damping term has the wrong sign: f2 =
// -ks (l - l0) e + kd v_rel e, so damping pushes the particles apart when they separate (adds
// energy).
// Task 1 — Spring::computeForce
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  const Vec2 d = p2->x - p1->x;
  const double l = d.norm();
  if (l < 1e-12) return Vec2::Zero();
  const Vec2 e = d / l;
  const double vRel = (p2->v - p1->v).dot(e);
  return -ks * (l - restLength) * e + kd * vRel * e;
}

}  // namespace a6
