// BROKEN SUBMISSION (grader test fixture, tests/grader/hostile_test.cpp): a compile error.
//
// The solution's forces.cpp with one line broken (a missing semicolon). Expected: task 2 is
// graded with the starter's stub (0 points) and the compiler's message is in the report; every
// other task keeps its points.
#include "a6/forces.h"

namespace a6 {

// Gravity: m g.
// clang-format off
Vec2 gravityForce(const Particle& p, const Vec2& g) { return p.m * g }  // the semicolon is missing
// clang-format on

// Buoyancy: b (T - T_air) (0, 1).
Vec2 buoyancyForce(const Particle& p, double b, double airTemperature) {
  return b * (p.temperature - airTemperature) * Vec2(0, 1);
}

// Drag: -k_d v.
Vec2 dragForce(const Particle& p, double kd) { return -kd * p.v; }

// Repulsion: k_r d n, only while inside the obstacle.
Vec2 repulsionForce(const Contact& contact, double kr) {
  if (contact.depth <= 0) return Vec2::Zero();
  return kr * contact.depth * contact.normal;
}

// All external forces on one particle.
Vec2 externalForce(const Particle& p, const Environment& env) {
  Vec2 f = gravityForce(p, env.gravity) + buoyancyForce(p, env.buoyancy, env.airTemperature) +
           dragForce(p, env.drag);
  for (const HalfPlane& plane : env.planes) {
    f += repulsionForce(contactWith(plane, p.x), env.repulsion);
  }
  for (const CircleObstacle& circle : env.circles) {
    f += repulsionForce(contactWith(circle, p.x), env.repulsion);
  }
  return f;
}

}  // namespace a6
