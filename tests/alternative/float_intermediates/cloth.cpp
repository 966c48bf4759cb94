// CORRECT ALTERNATIVE (task 4): the cloth with a float grid spacing and float rest lengths,
// springs added row by row in another order.
#include "a6/cloth.h"

#include <cmath>

namespace a6 {

void buildCloth(MassSpringSystem& system, const ClothSpec& spec) {
  const int n = spec.n;
  const float h = float(spec.size) / float(n);
  const int base = static_cast<int>(system.particles.size());
  auto at = [&](int i, int j) { return base + clothIndex(i, j, n); };
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      Particle p;
      p.x = spec.origin + Vec2(float(i) * h, -float(j) * h);
      p.m = spec.particleMass;
      system.addParticle(p);
    }
  }
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i < n; ++i)
      system.addSpring(at(i, j), at(i + 1, j), spec.ksStructural, spec.kdStructural,
                       SpringType::Structural, h);
  }
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j < n; ++j)
      system.addSpring(at(i, j), at(i, j + 1), spec.ksStructural, spec.kdStructural,
                       SpringType::Structural, h);
  }
  const float diagonal = std::sqrt(2.0f) * h;
  for (int j = 0; spec.shear && j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      system.addSpring(at(i + 1, j), at(i, j + 1), spec.ksShear, spec.kdShear, SpringType::Shear,
                       diagonal);
      system.addSpring(at(i, j), at(i + 1, j + 1), spec.ksShear, spec.kdShear, SpringType::Shear,
                       diagonal);
    }
  }
  for (int j = 0; spec.bending && j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      if (i + 2 <= n)
        system.addSpring(at(i, j), at(i + 2, j), spec.ksBending, spec.kdBending,
                         SpringType::Bending, 2.0f * h);
      if (j + 2 <= n)
        system.addSpring(at(i, j), at(i, j + 2), spec.ksBending, spec.kdBending,
                         SpringType::Bending, 2.0f * h);
    }
  }
  if (spec.pinTopCorners) {
    system.particles[at(n, 0)].pinned = true;
    system.particles[at(0, 0)].pinned = true;
  }
}

}  // namespace a6
