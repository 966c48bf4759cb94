// Task 4, the cloth builder: the mistakes of tests/wrong/t4_*, each the reference builder
// (reference/cloth.h) in the form that answers a ClothSpec as that wrong version does. Springs are
// compared as a set (ends in either order, any creation order), particles in the layout's order.
#include <optional>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"
#include "reference/cloth.h"

namespace a6::grader::mistakes {
namespace {

using harness::ClothResult;

enum class Flaw {
  None,
  BendingWrongStride,
  DuplicateSprings,
  IgnoresBase,
  MissingLastColumn,
  PinsBottomCorners,
  PinsIgnoreBase,
  ShearStructuralRest
};

// The reference builder's form that makes each mistake (reference/cloth.h).
reference::ClothForm formOf(Flaw flaw) {
  reference::ClothForm f;
  f.missingLastColumn = flaw == Flaw::MissingLastColumn;
  f.duplicateSprings = flaw == Flaw::DuplicateSprings;
  f.shearStructuralRest = flaw == Flaw::ShearStructuralRest;
  f.bendingWrongStride = flaw == Flaw::BendingWrongStride;
  f.pinsBottomCorners = flaw == Flaw::PinsBottomCorners;
  f.ignoresBase = flaw == Flaw::IgnoresBase;
  f.pinsIgnoreBase = flaw == Flaw::PinsIgnoreBase;
  return f;
}

bool same(const ClothResult& a, const ClothResult& b) {
  return reference::sameCloth(a, b, kTolerance);
}

// The cloth of a spec the checks asked for (none beyond 200 cells a side: not a check's).
std::optional<ClothResult> answer(const harness::ClothRequest& request, Flaw flaw) {
  if (request.spec.n < 1 || request.spec.n > 200) return std::nullopt;
  return reference::referenceCloth(request.spec, formOf(flaw));
}

}  // namespace

std::vector<MistakeModel> task4Mistakes() {
  const auto model = flawModels<harness::ClothRequest, Flaw>(4, answer, same);
  return {
      model("t4_missing_last_column", Flaw::MissingLastColumn,
            "Your cloth behaves exactly like one whose structural loop stops at i < n: the "
            "vertical springs (n,j)-(n,j+1) of the last column are missing; run i from 0 to n."),
      model("t4_duplicate_springs", Flaw::DuplicateSprings,
            "Your cloth behaves exactly like one that joins every particle to all four neighbours, "
            "so each structural spring is made twice; make (i,j)-(i+1,j) and (i,j)-(i,j+1) only."),
      model("t4_shear_with_structural_rest_length", Flaw::ShearStructuralRest,
            "Your cloth behaves exactly like one whose shear springs have the structural rest "
            "length h: a diagonal is sqrt(2) h long, so they start compressed."),
      model("t4_bending_wrong_stride", Flaw::BendingWrongStride,
            "Your cloth behaves exactly like one whose vertical bending springs step two rows "
            "down with a row width of n instead of n + 1: use at(i, j + 2), index k + 2(n + 1)."),
      model("t4_pins_bottom_corners", Flaw::PinsBottomCorners,
            "Your cloth behaves exactly like one that pins the bottom corners (0,n) and (n,n): "
            "row j = 0 is the top; pin (0,0) and (n,0)."),
      model("t4_ignores_base", Flaw::IgnoresBase,
            "Your cloth behaves exactly like one that forgets base, the number of particles the "
            "system held before: in a system that already holds particles its springs join the "
            "wrong ones; add base to every index."),
      model("t4_pins_ignore_base", Flaw::PinsIgnoreBase,
            "Your cloth behaves exactly like one whose springs use base but whose pins do not: "
            "pin particles base + clothIndex(0, 0, n) and base + clothIndex(n, 0, n)."),
  };
}

}  // namespace a6::grader::mistakes
