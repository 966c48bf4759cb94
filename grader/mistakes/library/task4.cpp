// Task 4, the cloth builder: the reference (n+1)x(n+1) grid after the prelude (base), its
// structural, shear and bending springs and its pinned top corners, and the mistakes of
// tests/wrong/t4_*, each answering a ClothSpec as that wrong version does. Springs are compared
// as a set (ends in either order, any creation order), particles in the layout's order.
#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"

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

struct Builder {
  const ClothSpec& spec;
  Flaw flaw;
  ClothResult out;
  int n = spec.n;
  double h = spec.size / spec.n;
  int base = 0;

  int at(int i, int j) const { return base + clothIndex(i, j, n); }
  void spring(int i, int j, double ks, double kd, SpringType type, double rest) {
    out.springs.push_back({i, j, rest, ks, kd, type});
  }
  void structural(int i, int j) {
    const ClothSpec& s = spec;
    if (i < n)
      spring(at(i, j), at(i + 1, j), s.ksStructural, s.kdStructural, SpringType::Structural, h);
    const bool lastColumn = flaw == Flaw::MissingLastColumn && i == n;
    if (j < n && !lastColumn)
      spring(at(i, j), at(i, j + 1), s.ksStructural, s.kdStructural, SpringType::Structural, h);
    if (flaw != Flaw::DuplicateSprings) return;
    if (i > 0)
      spring(at(i, j), at(i - 1, j), s.ksStructural, s.kdStructural, SpringType::Structural, h);
    if (j > 0)
      spring(at(i, j), at(i, j - 1), s.ksStructural, s.kdStructural, SpringType::Structural, h);
  }
  void shear(int i, int j) {
    const double rest = flaw == Flaw::ShearStructuralRest ? h : std::sqrt(2.0) * h;
    spring(at(i, j), at(i + 1, j + 1), spec.ksShear, spec.kdShear, SpringType::Shear, rest);
    spring(at(i + 1, j), at(i, j + 1), spec.ksShear, spec.kdShear, SpringType::Shear, rest);
  }
  void bending(int i, int j) {
    const ClothSpec& s = spec;
    if (i + 2 <= n)
      spring(at(i, j), at(i + 2, j), s.ksBending, s.kdBending, SpringType::Bending, 2 * h);
    const int below = flaw == Flaw::BendingWrongStride ? at(i, j) + 2 * n : at(i, j + 2);
    if (j + 2 <= n) spring(at(i, j), below, s.ksBending, s.kdBending, SpringType::Bending, 2 * h);
  }
  void pin() {
    const int row = flaw == Flaw::PinsBottomCorners ? n : 0;
    const int offset = flaw == Flaw::PinsIgnoreBase ? -base : 0;
    for (int i : {0, n}) out.particles[static_cast<std::size_t>(at(i, row) + offset)].pinned = true;
  }
};

ClothResult cloth(const ClothSpec& spec, Flaw flaw) {
  const harness::ClothPrelude& prelude = harness::clothPrelude();
  Builder b{spec, flaw, {}};
  b.out.particles = prelude.particles;
  b.out.springs = prelude.springs;
  b.base = flaw == Flaw::IgnoresBase ? 0 : static_cast<int>(prelude.particles.size());
  for (int j = 0; j <= b.n; ++j) {
    for (int i = 0; i <= b.n; ++i) {
      Particle p;
      p.x = spec.origin + Vec2(i, -j) * b.h;
      p.m = spec.particleMass;
      b.out.particles.push_back(p);
    }
  }
  for (int j = 0; j <= b.n; ++j)
    for (int i = 0; i <= b.n; ++i) b.structural(i, j);
  for (int j = 0; spec.shear && j < b.n; ++j)
    for (int i = 0; i < b.n; ++i) b.shear(i, j);
  for (int j = 0; spec.bending && j <= b.n; ++j)
    for (int i = 0; i <= b.n; ++i) b.bending(i, j);
  if (spec.pinTopCorners) b.pin();
  return b.out;
}

// A spring as a sortable key: its ends in order, type, then its constants.
std::vector<std::tuple<int, int, int, double, double, double>> springSet(const ClothResult& c) {
  std::vector<std::tuple<int, int, int, double, double, double>> keys;
  for (const SpringData& s : c.springs) {
    keys.emplace_back(std::min(s.i, s.j), std::max(s.i, s.j), static_cast<int>(s.type),
                      s.restLength, s.ks, s.kd);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

bool sameParticles(const ClothResult& a, const ClothResult& b) {
  if (a.particles.size() != b.particles.size()) return false;
  for (std::size_t k = 0; k < a.particles.size(); ++k) {
    const Particle &p = a.particles[k], &q = b.particles[k];
    if (!near(p.x, q.x, 1.0) || !near(p.m, q.m) || p.pinned != q.pinned) return false;
  }
  return true;
}

bool same(const ClothResult& a, const ClothResult& b) {
  if (!sameParticles(a, b)) return false;
  const auto sa = springSet(a), sb = springSet(b);
  if (sa.size() != sb.size()) return false;
  for (std::size_t k = 0; k < sa.size(); ++k) {
    const auto &x = sa[k], &y = sb[k];
    if (std::get<0>(x) != std::get<0>(y) || std::get<1>(x) != std::get<1>(y) ||
        std::get<2>(x) != std::get<2>(y) || !near(std::get<3>(x), std::get<3>(y)) ||
        !near(std::get<4>(x), std::get<4>(y)) || !near(std::get<5>(x), std::get<5>(y)))
      return false;
  }
  return true;
}

// The cloth of a spec the checks asked for (none beyond 200 cells a side: not a check's).
std::optional<ClothResult> answer(const harness::ClothRequest& request, Flaw flaw) {
  if (request.spec.n < 1 || request.spec.n > 200) return std::nullopt;
  return cloth(request.spec, flaw);
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
