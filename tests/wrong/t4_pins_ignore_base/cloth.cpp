// WRONG VERSION (task 4): the springs use base, the pins do not: in a system that already holds
// particles, the wrong particles are pinned. Only the check of base may fail.
// Task 4 — the mass-spring cloth (slides "Mass-spring cloth", "Cloth springs", "Extra springs").
#include "a6/cloth.h"

#include <cmath>

namespace a6 {

void buildCloth(MassSpringSystem& system, const ClothSpec& spec) {
  const int n = spec.n;
  const double h = spec.size / n;
  const int base = static_cast<int>(system.particles.size());
  auto at = [&](int i, int j) { return base + clothIndex(i, j, n); };

  // (n+1) x (n+1) particles: (i, j) at origin + (i, -j) h.
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      Particle p;
      p.x = spec.origin + Vec2(i, -j) * h;
      p.m = spec.particleMass;
      system.addParticle(p);
    }
  }

  // Structural springs: (i,j)-(i+1,j) and (i,j)-(i,j+1), rest length h.
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      if (i < n)
        system.addSpring(at(i, j), at(i + 1, j), spec.ksStructural, spec.kdStructural,
                         SpringType::Structural, h);
      if (j < n)
        system.addSpring(at(i, j), at(i, j + 1), spec.ksStructural, spec.kdStructural,
                         SpringType::Structural, h);
    }
  }

  // Shear springs: (i,j)-(i+1,j+1) and (i+1,j)-(i,j+1), rest length sqrt(2) h.
  if (spec.shear) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        system.addSpring(at(i, j), at(i + 1, j + 1), spec.ksShear, spec.kdShear, SpringType::Shear,
                         std::sqrt(2.0) * h);
        system.addSpring(at(i + 1, j), at(i, j + 1), spec.ksShear, spec.kdShear, SpringType::Shear,
                         std::sqrt(2.0) * h);
      }
    }
  }

  // Bending springs (the extension): (i,j)-(i+2,j) and (i,j)-(i,j+2), rest length 2h.
  if (spec.bending) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        if (i + 2 <= n)
          system.addSpring(at(i, j), at(i + 2, j), spec.ksBending, spec.kdBending,
                           SpringType::Bending, 2 * h);
        if (j + 2 <= n)
          system.addSpring(at(i, j), at(i, j + 2), spec.ksBending, spec.kdBending,
                           SpringType::Bending, 2 * h);
      }
    }
  }

  // Pin the top corners.
  if (spec.pinTopCorners) {
    system.particles[clothIndex(0, 0, n)].pinned = true;
    system.particles[clothIndex(n, 0, n)].pinned = true;
  }
}

}  // namespace a6
