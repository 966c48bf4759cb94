// Task 4 — the mass-spring cloth
// Slides: "Mass-spring cloth", "Cloth springs", "Extra springs".
//
// An n x n cloth has (n+1) x (n+1) particles. With h = size / n, particle (i, j) — column i
// from the left, row j from the top — goes at
//
//     particles[base + clothIndex(i, j, n)]   at position   origin + (i, -j) h
//
// (base = system.particles.size() before you start; use system.addParticle). Then the springs
// (system.addSpring(a, b, ks, kd, type, restLength)):
//
//     structural  (i,j)-(i+1,j) and (i,j)-(i,j+1)       rest length h         ksStructural,
//     kdStructural shear       (i,j)-(i+1,j+1) and (i+1,j)-(i,j+1)   rest length sqrt(2) h ksShear,
//     kdShear     (if spec.shear) bending     (i,j)-(i+2,j) and (i,j)-(i,j+2)       rest length 2 h
//     ksBending, kdBending (if spec.bending)
//
// and pin the two top corners (0,0) and (n,0) when spec.pinTopCorners.
// Mind the edges: no spring may reach outside the grid, and none may appear twice.
//
// Done when: `ctest -R Task4` passes (tests named Task4Cloth.*): the particle count and
// positions, (n+1)² particles, 2n(n+1) structural, 2n² shear and 2(n-1)(n+1) bending springs,
// no duplicates, the right rest lengths and constants, and the pinned corners.
#include "a6/cloth.h"

namespace a6 {

void buildCloth(MassSpringSystem& system, const ClothSpec& spec) {
  // TODO(task 4): particles, structural, shear, bending springs, pins.
}

}  // namespace a6
