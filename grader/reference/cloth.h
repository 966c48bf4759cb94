// The reference cloth builder (task 4): the (n+1)x(n+1) grid appended after what the system
// held (harness::clothPrelude(), from base on), its structural, shear and bending springs and its
// pinned top corners, in a form whose default is the physics'. The hidden checks compare with
// the default form; the mistake library's models of task 4 run the wrong forms. Takes a spec;
// gives the system as buildCloth leaves it. Graders' material, as physics.inc.
#pragma once

#include "harness/student_code.h"

namespace a6::grader::reference {

// One form of the builder, part by part; the default is the physics'.
struct ClothForm {
  bool missingLastColumn = false;    ///< the structural loop stops at i < n: no (n,j)-(n,j+1)
  bool duplicateSprings = false;     ///< every particle joined to all four neighbours
  bool shearStructuralRest = false;  ///< shear springs at rest length h, not sqrt(2) h
  bool bendingWrongStride = false;   ///< vertical bending springs to index k + 2n, not k + 2(n+1)
  bool pinsBottomCorners = false;    ///< (0,n) and (n,n) pinned, not (0,0) and (n,0)
  bool ignoresBase = false;          ///< indices from 0, not from base
  bool pinsIgnoreBase = false;       ///< springs from base, pins from 0
};

/// The system after buildCloth(spec) on one holding clothPrelude(), in `form`.
harness::ClothResult referenceCloth(const ClothSpec& spec, const ClothForm& form = {});

/// The same cloth: particles in order (positions, masses, pins), springs as a set (ends in
/// either order, any creation order), each within `relative` of the other's values.
bool sameCloth(const harness::ClothResult& a, const harness::ClothResult& b,
               double relative = 1e-9);

}  // namespace a6::grader::reference
