// Task 2 — the forces
// Slide: "Some forces".
//
//     gravity      f = m g
//     buoyancy     f = b (T - T_air) (0, 1)       hot particles rise, cold ones sink
//     drag         f = -k_d v
//     repulsion    f = k_r d n                    only while the particle is inside an obstacle
//
// For repulsion the framework measures the contact for you: contactWith(obstacle, x) returns
// the penetration depth d (> 0 only when inside) and the unit normal n pointing out of the
// obstacle (see a6/forces.h).
//
// What to write: the five functions below (N, world frame). externalForce adds them all up for
// one particle: gravity + buoyancy + drag + the repulsion of every half-plane and every circle
// in env.
//
// Done when: `ctest -R Task2` passes (tests named Task2Forces.*): each force on its own, in any
// direction, and their sum in externalForce.
#include "a6/forces.h"

namespace a6 {

Vec2 gravityForce(const Particle& p, const Vec2& g) {
  // TODO(task 2): m g
  return Vec2::Zero();
}

Vec2 buoyancyForce(const Particle& p, double b, double airTemperature) {
  // TODO(task 2): b (T - T_air) (0, 1)
  return Vec2::Zero();
}

Vec2 dragForce(const Particle& p, double kd) {
  // TODO(task 2): -k_d v
  return Vec2::Zero();
}

Vec2 repulsionForce(const Contact& contact, double kr) {
  // TODO(task 2): k_r d n while contact.depth > 0, zero otherwise
  return Vec2::Zero();
}

Vec2 externalForce(const Particle& p, const Environment& env) {
  // TODO(task 2): gravity + buoyancy + drag, plus
  //   repulsionForce(contactWith(plane, p.x), env.repulsion) for each plane in env.planes
  //   and the same for each circle in env.circles.
  return Vec2::Zero();
}

}  // namespace a6
