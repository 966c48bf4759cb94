// Task 4 — the mass-spring cloth
#include "a6/cloth.h"

#include <cmath>

namespace a6 {

void buildCloth(MassSpringSystem& system, const ClothSpec& spec) {
  const int n = spec.n;
  const double h = spec.size / n;
  const int base = static_cast<int>(system.particles.size());
  auto idx = [&](int i, int j) { return base + clothIndex(i, j, n); };

  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      Particle p;
      p.x = spec.origin + Vec2(i, -j) * h;
      p.m = spec.particleMass;
      system.addParticle(p);
    }
  }

  // Structural.
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      if (i < n)
        system.addSpring(idx(i, j), idx(i + 1, j), spec.ksStructural, spec.kdStructural,
                         SpringType::Structural, h);
      if (j < n)
        system.addSpring(idx(i, j), idx(i, j + 1), spec.ksStructural, spec.kdStructural,
                         SpringType::Structural, h);
    }
  }

  // Shear.
  if (spec.shear) {
    const double rl = std::sqrt(2.0) * h;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        system.addSpring(idx(i, j), idx(i + 1, j + 1), spec.ksShear, spec.kdShear,
                         SpringType::Shear, rl);
        system.addSpring(idx(i + 1, j), idx(i, j + 1), spec.ksShear, spec.kdShear,
                         SpringType::Shear, rl);
      }
    }
  }

  // Bending.
  if (spec.bending) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        if (i + 2 <= n)
          system.addSpring(idx(i, j), idx(i + 2, j), spec.ksBending, spec.kdBending,
                           SpringType::Bending, 2 * h);
        if (j + 2 <= n)
          system.addSpring(idx(i, j), idx(i, j + 2), spec.ksBending, spec.kdBending,
                           SpringType::Bending, 2 * h);
      }
    }
  }

  if (spec.pinTopCorners) {
    system.particles[idx(0, 0)].pinned = true;
    system.particles[idx(n, 0)].pinned = true;
  }
}

}  // namespace a6
