// buildCloth runs on a system that already holds particles and springs (harness::clothPrelude()):
// the cloth checks look at the cloth's own part, with indices relative to base, after checking
// that the builder appended after the prelude and left it alone.
#pragma once

#include <algorithm>
#include <string>

#include "harness/student_code.h"

namespace a6::test {

/// What the builder did wrong to the system's earlier content, in words; empty when nothing.
inline std::string preludeProblem(const harness::ClothResult& r) {
  const harness::ClothPrelude& prelude = harness::clothPrelude();
  const int base = static_cast<int>(prelude.particles.size());
  if (r.particles.size() < prelude.particles.size() || r.springs.size() < prelude.springs.size()) {
    return "the system held " + std::to_string(base) + " particles and " +
           std::to_string(prelude.springs.size()) + " springs before buildCloth, and fewer after";
  }
  for (int k = 0; k < base; ++k) {
    const Particle& before = prelude.particles[static_cast<std::size_t>(k)];
    const Particle& after = r.particles[static_cast<std::size_t>(k)];
    if (before.x != after.x || before.v != after.v || before.m != after.m ||
        before.pinned != after.pinned) {
      return "particle " + std::to_string(k) + ", which the system held before the cloth, was " +
             (before.pinned != after.pinned ? std::string(after.pinned ? "pinned" : "unpinned")
                                            : std::string("changed")) +
             " by buildCloth (pin the cloth's corners at base + clothIndex(0, 0, n) and "
             "base + clothIndex(n, 0, n))";
    }
  }
  for (std::size_t k = prelude.springs.size(); k < r.springs.size(); ++k) {
    const SpringData& s = r.springs[k];
    if ((s.i >= 0 && s.i < base) || (s.j >= 0 && s.j < base)) {
      return "a cloth spring joins particles " + std::to_string(s.i) + " and " +
             std::to_string(s.j) + ", but particles 0 to " + std::to_string(base - 1) +
             " are what the system held before the cloth";
    }
  }
  return "";
}

/// The hint for a prelude problem.
inline std::string preludeAdvice() {
  return "the system may already hold particles: the cloth's particle (i,j) is "
         "particles[base + clothIndex(i,j,n)] with base = system.particles.size() before the "
         "cloth's first particle; use base in addSpring and when pinning";
}

/// True when the system's first particles are still the prelude's (pins aside: a builder that
/// forgot base pins them); false when the builder replaced the system's content.
inline bool preludeKept(const harness::ClothResult& r) {
  const harness::ClothPrelude& prelude = harness::clothPrelude();
  if (r.particles.size() < prelude.particles.size()) return false;
  for (std::size_t k = 0; k < prelude.particles.size(); ++k) {
    const Particle& before = prelude.particles[k];
    const Particle& after = r.particles[k];
    if (before.x != after.x || before.v != after.v || before.m != after.m) return false;
  }
  return true;
}

/// The cloth's particles and springs of an n x n cloth, with indices relative to base. A builder
/// that got base wrong is read as it meant it, so that the one mistake costs the one check that
/// names it (Task4Cloth.BuildsAfterWhatTheSystemAlreadyHolds), not every cloth check; its
/// springs and its pins are judged apart:
///   - springs that reach into the prelude were indexed as if the system were empty;
///   - a pinned prelude particle means the pins were (particle k of the cloth is then read as
///     pinned when the system's particle k is);
///   - a builder that replaced the system's content (cleared or resized it) made the whole
///     system: all of it is read as the cloth.
inline harness::ClothResult clothPart(const harness::ClothResult& r, int n) {
  const harness::ClothPrelude& prelude = harness::clothPrelude();
  const int base = static_cast<int>(prelude.particles.size());
  harness::ClothResult out;
  out.error = r.error;
  std::size_t firstSpring = 0;
  if (r.springs.size() >= prelude.springs.size() &&
      std::equal(prelude.springs.begin(), prelude.springs.end(), r.springs.begin(),
                 [](const SpringData& a, const SpringData& b) {
                   return a.i == b.i && a.j == b.j && a.restLength == b.restLength &&
                          a.ks == b.ks && a.kd == b.kd && a.type == b.type;
                 })) {
    firstSpring = prelude.springs.size();
  }
  if (!preludeKept(r)) {
    out.particles = r.particles;
    out.springs.assign(r.springs.begin() + static_cast<std::ptrdiff_t>(firstSpring),
                       r.springs.end());
    return out;
  }
  out.particles.assign(r.particles.begin() + base, r.particles.end());
  bool springsAsIfEmpty = false, pinsAsIfEmpty = false;
  for (std::size_t k = firstSpring; k < r.springs.size(); ++k) {
    const SpringData& s = r.springs[k];
    springsAsIfEmpty = springsAsIfEmpty || (s.i >= 0 && s.i < base) || (s.j >= 0 && s.j < base);
  }
  for (int k = 0; k < base; ++k)
    pinsAsIfEmpty = pinsAsIfEmpty || r.particles[static_cast<std::size_t>(k)].pinned;
  if (pinsAsIfEmpty) {
    const std::size_t cloth =
        std::min(out.particles.size(), static_cast<std::size_t>((n + 1) * (n + 1)));
    for (std::size_t k = 0; k < cloth && k < r.particles.size(); ++k)
      out.particles[k].pinned = r.particles[k].pinned;
  }
  const int shift = springsAsIfEmpty ? 0 : base;
  for (std::size_t k = firstSpring; k < r.springs.size(); ++k) {
    SpringData s = r.springs[k];
    s.i = s.i < 0 ? s.i : s.i - shift;
    s.j = s.j < 0 ? s.j : s.j - shift;
    out.springs.push_back(s);
  }
  return out;
}

}  // namespace a6::test
