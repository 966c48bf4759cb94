// buildCloth runs on a system that already holds particles and springs (harness::clothPrelude()):
// the cloth checks look at the cloth's own part, with indices relative to base, after checking
// that the builder appended after the prelude and left it alone.
#pragma once

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

/// The cloth's particles and springs, with indices relative to base. A builder that indexed as
/// if the system were empty (preludeProblem) is read as it meant it: its spring indices and its
/// pins are taken as the cloth's own, so that the one mistake costs the one check that names it
/// (Task4Cloth.BuildsAfterWhatTheSystemAlreadyHolds), not every cloth check.
inline harness::ClothResult clothPart(const harness::ClothResult& r) {
  const harness::ClothPrelude& prelude = harness::clothPrelude();
  const std::size_t base = prelude.particles.size();
  const bool asIfEmpty = !preludeProblem(r).empty();
  harness::ClothResult out;
  out.error = r.error;
  if (r.particles.size() >= base)
    out.particles.assign(r.particles.begin() + base, r.particles.end());
  if (asIfEmpty) {
    for (std::size_t k = 0; k < out.particles.size(); ++k)
      out.particles[k].pinned = r.particles[k].pinned;
  }
  const int shift = asIfEmpty ? 0 : static_cast<int>(base);
  for (std::size_t k = std::min(prelude.springs.size(), r.springs.size()); k < r.springs.size();
       ++k) {
    SpringData s = r.springs[k];
    s.i = s.i < 0 ? s.i : s.i - shift;
    s.j = s.j < 0 ? s.j : s.j - shift;
    out.springs.push_back(s);
  }
  return out;
}

}  // namespace a6::test
