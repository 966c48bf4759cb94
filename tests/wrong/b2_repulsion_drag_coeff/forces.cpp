// WRONG VERSION (task 2, written blind from the handout): externalForce passes the drag coefficient
// env.drag instead of the repulsion stiffness env.repulsion to repulsionForce for every plane and
// circle.
// Task 2 — the forces
#include "a6/forces.h"

namespace a6 {

Vec2 gravityForce(const Particle& p, const Vec2& g) { return p.m * g; }

Vec2 buoyancyForce(const Particle& p, double b, double airTemperature) {
  return Vec2(0.0, b * (p.temperature - airTemperature));
}

Vec2 dragForce(const Particle& p, double kd) { return -kd * p.v; }

Vec2 repulsionForce(const Contact& contact, double kr) {
  if (contact.depth > 0) return kr * contact.depth * contact.normal;
  return Vec2::Zero();
}

Vec2 externalForce(const Particle& p, const Environment& env) {
  Vec2 f = gravityForce(p, env.gravity) + buoyancyForce(p, env.buoyancy, env.airTemperature) +
           dragForce(p, env.drag);
  for (const HalfPlane& plane : env.planes) f += repulsionForce(contactWith(plane, p.x), env.drag);
  for (const CircleObstacle& circle : env.circles)
    f += repulsionForce(contactWith(circle, p.x), env.drag);
  return f;
}

}  // namespace a6
