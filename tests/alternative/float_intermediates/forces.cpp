// CORRECT ALTERNATIVE (task 2): the forces with float intermediates.
#include "a6/forces.h"

namespace a6 {

namespace {
Vec2 toDouble(const Eigen::Vector2f& v) { return v.cast<double>(); }
}  // namespace

Vec2 gravityForce(const Particle& p, const Vec2& g) {
  return toDouble(float(p.m) * g.cast<float>());
}

Vec2 buoyancyForce(const Particle& p, double b, double airTemperature) {
  const float size = float(b) * (float(p.temperature) - float(airTemperature));
  return Vec2(0, size);
}

Vec2 dragForce(const Particle& p, double kd) { return toDouble(-float(kd) * p.v.cast<float>()); }

Vec2 repulsionForce(const Contact& contact, double kr) {
  const float depth = float(contact.depth);
  if (depth <= 0) return Vec2::Zero();
  return toDouble(float(kr) * depth * contact.normal.cast<float>());
}

Vec2 externalForce(const Particle& p, const Environment& env) {
  Eigen::Vector2f f = gravityForce(p, env.gravity).cast<float>();
  f += buoyancyForce(p, env.buoyancy, env.airTemperature).cast<float>();
  f += dragForce(p, env.drag).cast<float>();
  for (const HalfPlane& plane : env.planes) {
    f += repulsionForce(contactWith(plane, p.x), env.repulsion).cast<float>();
  }
  for (const CircleObstacle& circle : env.circles) {
    f += repulsionForce(contactWith(circle, p.x), env.repulsion).cast<float>();
  }
  return toDouble(f);
}

}  // namespace a6
