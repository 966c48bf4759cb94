// The reference cloth builder, in forms (see cloth.h).
#include "reference/cloth.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace a6::grader::reference {
namespace {

using harness::ClothResult;

// Builds the grid's springs and pins into `out`, the particles (i, j) at base + clothIndex(i, j).
struct Builder {
  const ClothSpec& spec;
  const ClothForm& form;
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
    const bool lastColumn = form.missingLastColumn && i == n;
    if (j < n && !lastColumn)
      spring(at(i, j), at(i, j + 1), s.ksStructural, s.kdStructural, SpringType::Structural, h);
    if (!form.duplicateSprings) return;
    if (i > 0)
      spring(at(i, j), at(i - 1, j), s.ksStructural, s.kdStructural, SpringType::Structural, h);
    if (j > 0)
      spring(at(i, j), at(i, j - 1), s.ksStructural, s.kdStructural, SpringType::Structural, h);
  }
  void shear(int i, int j) {
    const double rest = form.shearStructuralRest ? h : std::sqrt(2.0) * h;
    spring(at(i, j), at(i + 1, j + 1), spec.ksShear, spec.kdShear, SpringType::Shear, rest);
    spring(at(i + 1, j), at(i, j + 1), spec.ksShear, spec.kdShear, SpringType::Shear, rest);
  }
  void bending(int i, int j) {
    const ClothSpec& s = spec;
    if (i + 2 <= n)
      spring(at(i, j), at(i + 2, j), s.ksBending, s.kdBending, SpringType::Bending, 2 * h);
    const int below = form.bendingWrongStride ? at(i, j) + 2 * n : at(i, j + 2);
    if (j + 2 <= n) spring(at(i, j), below, s.ksBending, s.kdBending, SpringType::Bending, 2 * h);
  }
  void pin() {
    const int row = form.pinsBottomCorners ? n : 0;
    const int offset = form.pinsIgnoreBase ? -base : 0;
    for (int i : {0, n}) out.particles[static_cast<std::size_t>(at(i, row) + offset)].pinned = true;
  }
};

// a and b within `tolerance` (NaN is close only to NaN, infinity only to itself).
bool within(double a, double b, double tolerance) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= tolerance + 1e-12;
}
bool near(double a, double b, double relative) {
  return within(a, b, relative * std::max(std::abs(a), std::abs(b)));
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

bool sameParticles(const ClothResult& a, const ClothResult& b, double relative) {
  if (a.particles.size() != b.particles.size()) return false;
  for (std::size_t k = 0; k < a.particles.size(); ++k) {
    const Particle &p = a.particles[k], &q = b.particles[k];
    // Positions within `relative` of a metre, as the grid's scale.
    if (!within(p.x.x(), q.x.x(), relative) || !within(p.x.y(), q.x.y(), relative)) return false;
    if (!near(p.m, q.m, relative) || p.pinned != q.pinned) return false;
  }
  return true;
}

}  // namespace

ClothResult referenceCloth(const ClothSpec& spec, const ClothForm& form) {
  const harness::ClothPrelude& prelude = harness::clothPrelude();
  Builder b{spec, form, {}};
  b.out.particles = prelude.particles;
  b.out.springs = prelude.springs;
  b.base = form.ignoresBase ? 0 : static_cast<int>(prelude.particles.size());
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

bool sameCloth(const ClothResult& a, const ClothResult& b, double relative) {
  if (!sameParticles(a, b, relative)) return false;
  const auto sa = springSet(a), sb = springSet(b);
  if (sa.size() != sb.size()) return false;
  for (std::size_t k = 0; k < sa.size(); ++k) {
    const auto &x = sa[k], &y = sb[k];
    if (std::get<0>(x) != std::get<0>(y) || std::get<1>(x) != std::get<1>(y) ||
        std::get<2>(x) != std::get<2>(y) || !near(std::get<3>(x), std::get<3>(y), relative) ||
        !near(std::get<4>(x), std::get<4>(y), relative) ||
        !near(std::get<5>(x), std::get<5>(y), relative))
      return false;
  }
  return true;
}

}  // namespace a6::grader::reference
