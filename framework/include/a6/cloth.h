// Task 4: the mass-spring cloth (slides "Mass-spring cloth", "Cloth springs", "Extra springs").
#pragma once

#include "a6/mass_spring_system.h"

namespace a6 {

/// A square cloth of n x n cells, hanging in the x-y plane.
struct ClothSpec {
  int n = 10;                  ///< cells per side: (n+1)² particles
  double size = 1.0;           ///< side length, m; grid spacing h = size / n
  Vec2 origin = Vec2(0, 0);    ///< position of particle (0,0), the top-left corner, m
  double particleMass = 0.01;  ///< mass of each particle, kg

  double ksStructural = 200;  ///< N/m
  double kdStructural = 0.2;  ///< N·s/m
  bool shear = true;          ///< add shear springs
  double ksShear = 50;        ///< N/m (lower than structural)
  double kdShear = 0.05;      ///< N·s/m
  bool bending = false;       ///< add bending springs (the extension)
  double ksBending = 20;      ///< N/m
  double kdBending = 0.02;    ///< N·s/m
  bool pinTopCorners = true;  ///< pin particles (0,0) and (n,0)
};

/// The index layout of the cloth (a contract the tests rely on): particle (i, j), with
/// i the column (0..n, left to right) and j the row (0..n, top to bottom), is
/// particles[base + clothIndex(i, j, n)], at origin + (i, -j) * size / n, where base is the
/// number of particles the system had before buildCloth.
inline int clothIndex(int i, int j, int n) { return j * (n + 1) + i; }

/// TASK 4 (cloth.cpp). Appends the cloth's particles and springs to `system`:
///   structural (i,j)-(i+1,j) and (i,j)-(i,j+1), rest length h;
///   shear (i,j)-(i+1,j+1) and (i+1,j)-(i,j+1), rest length sqrt(2) h, when spec.shear;
///   bending (i,j)-(i+2,j) and (i,j)-(i,j+2), rest length 2 h, when spec.bending;
/// each with the constants of its type and tagged with its SpringType; pins the top corners.
void buildCloth(MassSpringSystem& system, const ClothSpec& spec);

}  // namespace a6
