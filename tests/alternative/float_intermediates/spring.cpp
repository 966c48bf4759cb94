// CORRECT ALTERNATIVE (task 1): the slide's spring force with float intermediates.
#include "a6/spring.h"

namespace a6 {

Vec2 Spring::computeForce() const {
  const Eigen::Vector2f d = (p2->x - p1->x).cast<float>();
  const float l = d.norm();
  if (l < 1e-3f) return Vec2::Zero();  // a larger guard than the reference's: 1 mm
  const Eigen::Vector2f e = d / l;
  const float vRel = (p2->v - p1->v).cast<float>().dot(e);
  const float size = -float(ks) * (l - float(restLength)) - float(kd) * vRel;
  return (size * e).cast<double>();
}

}  // namespace a6
