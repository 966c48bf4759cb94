// WRONG VERSION (task 2): externalForce stops at the first obstacle the particle is inside: a
// particle in two obstacles at once (a corner, a circle on the floor) is pushed by one only.
// Task 2 — the forces (slide "Some forces").
#include "a6/forces.h"

namespace a6 {

// Gravity: m g.
Vec2 gravityForce(const Particle& p, const Vec2& g) { return p.m * g; }

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
  // The first obstacle the particle is inside pushes it; the rest are never looked at.
  for (const HalfPlane& plane : env.planes) {
    const Vec2 push = repulsionForce(contactWith(plane, p.x), env.repulsion);
    if (push != Vec2::Zero()) return f + push;
  }
  for (const CircleObstacle& circle : env.circles) {
    const Vec2 push = repulsionForce(contactWith(circle, p.x), env.repulsion);
    if (push != Vec2::Zero()) return f + push;
  }
  return f;
}

}  // namespace a6
