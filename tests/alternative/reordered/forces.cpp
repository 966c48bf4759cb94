// Alternative (correct) task 2: the same forces, written differently and summed in another
// order (obstacles first, circles before planes, gravity last).
#include "a6/forces.h"

namespace a6 {

Vec2 gravityForce(const Particle& p, const Vec2& g) { return g * p.m; }

Vec2 buoyancyForce(const Particle& p, double b, double airTemperature) {
  return Vec2(0.0, b * (p.temperature - airTemperature));
}

Vec2 dragForce(const Particle& p, double kd) { return p.v * (-kd); }

Vec2 repulsionForce(const Contact& contact, double kr) {
  return contact.depth > 0 ? Vec2(contact.normal * (kr * contact.depth)) : Vec2(0.0, 0.0);
}

Vec2 externalForce(const Particle& p, const Environment& env) {
  Vec2 f(0.0, 0.0);
  for (auto it = env.circles.rbegin(); it != env.circles.rend(); ++it) {
    f += repulsionForce(contactWith(*it, p.x), env.repulsion);
  }
  for (auto it = env.planes.rbegin(); it != env.planes.rend(); ++it) {
    f += repulsionForce(contactWith(*it, p.x), env.repulsion);
  }
  f += dragForce(p, env.drag);
  f += buoyancyForce(p, env.buoyancy, env.airTemperature);
  f += gravityForce(p, env.gravity);
  return f;
}

}  // namespace a6
