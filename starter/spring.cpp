// Task 1 — Spring::computeForce
// Slides: "Spring forces", "Spring implementation".
//
// A damped spring between particles p1 and p2 pulls them back towards its rest length l0.
// The slide's formula, for the force on the SECOND particle p2:
//
//     d = x2 - x1           l = |d|           e = d / l
//     v_rel = (v2 - v1) · e                  (relative speed ALONG the spring)
//     f2 = -ks (l - l0) e  -  kd v_rel e
//
// and p1 gets the opposite, f1 = -f2 (Newton's third law; step() applies it, task 3).
//
// What to write: Spring::computeForce() below, returning f2 (N, world frame).
//   - Fields you need: p1->x, p1->v, p2->x, p2->v, restLength, ks, kd (see a6/spring.h).
//   - If the particles coincide (l < 1e-12) there is no direction: return zero, never NaN.
//   - Damping acts only along e: project the relative velocity on e first.
//
// Done when: `ctest -R Task1` passes (tests named Task1Spring.*). They check a spring at rest,
// stretched and compressed in every direction, damping only along the spring, and Newton's
// third law.
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  // TODO(task 1): compute d, l and e; return -ks (l - l0) e - kd v_rel e.
  return Vec2::Zero();
}

}  // namespace a6
