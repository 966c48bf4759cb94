// Alternative (correct) task 4: the same cloth, built in another order. Particles come from a
// single loop over their index (the layout is the contract); springs are made column by
// column, bending before shear before structural, with p1 and p2 swapped in every pair; the
// corners are pinned as the particles are made.
#include "a6/cloth.h"

#include <cmath>

namespace a6 {

void buildCloth(MassSpringSystem& system, const ClothSpec& spec) {
  const int n = spec.n;
  const int side = n + 1;
  const double h = spec.size / n;
  const int base = static_cast<int>(system.particles.size());
  auto at = [&](int i, int j) { return base + clothIndex(i, j, n); };

  for (int k = 0; k < side * side; ++k) {
    const int i = k % side, j = k / side;
    Particle p;
    p.x = Vec2(spec.origin.x() + i * h, spec.origin.y() - j * h);
    p.m = spec.particleMass;
    p.pinned = spec.pinTopCorners && j == 0 && (i == 0 || i == n);
    system.addParticle(p);
  }

  for (int i = n; i >= 0; --i) {
    for (int j = n; j >= 0; --j) {
      if (spec.bending) {
        if (j + 2 <= n) {
          system.addSpring(at(i, j + 2), at(i, j), spec.ksBending, spec.kdBending,
                           SpringType::Bending, h + h);
        }
        if (i + 2 <= n) {
          system.addSpring(at(i + 2, j), at(i, j), spec.ksBending, spec.kdBending,
                           SpringType::Bending, h + h);
        }
      }
      if (spec.shear && i < n && j < n) {
        system.addSpring(at(i, j + 1), at(i + 1, j), spec.ksShear, spec.kdShear, SpringType::Shear,
                         std::hypot(h, h));
        system.addSpring(at(i + 1, j + 1), at(i, j), spec.ksShear, spec.kdShear, SpringType::Shear,
                         std::hypot(h, h));
      }
      if (j < n) {
        system.addSpring(at(i, j + 1), at(i, j), spec.ksStructural, spec.kdStructural,
                         SpringType::Structural, h);
      }
      if (i < n) {
        system.addSpring(at(i + 1, j), at(i, j), spec.ksStructural, spec.kdStructural,
                         SpringType::Structural, h);
      }
    }
  }
}

}  // namespace a6
