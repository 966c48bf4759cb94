// Task 1, the spring force: the reference's (reference/physics.inc), and the catalogue's mistake of
// the guard for coincident particles (tests/wrong/t1_nan_*). The terms' mistakes are named part by
// part (parts.cpp).
#include <optional>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"

namespace a6::grader::mistakes {
namespace {

using harness::SpringForceRequest;

#include "reference/physics.inc"

// The force with no guard for coincident ends: e = d / l is NaN when l = 0.
Vec2 unguardedForce(const SpringForceRequest& r) {
  const Vec2 d = r.p2.x - r.p1.x;
  const double l = d.norm();
  const Vec2 e = d / l;
  return -r.ks * (l - r.restLength) * e - r.kd * (r.p2.v - r.p1.v).dot(e) * e;
}

// The answer as the checks get it, with or without (`unguarded`) the guard.
std::optional<harness::SpringForceResult> answer(const SpringForceRequest& r, bool unguarded) {
  harness::SpringForceResult out;
  if (unguarded) {
    out.force = unguardedForce(r);
  } else {
    const SpringTerms t = referenceSpringTerms(r.p1, r.p2, r.restLength, r.ks, r.kd);
    out.force = t.elastic + t.damping;
  }
  return out;
}

bool same(const harness::SpringForceResult& a, const harness::SpringForceResult& b) {
  return near(a.force, b.force);
}

}  // namespace

std::vector<MistakeModel> task1Mistakes() {
  const auto model = flawModels<SpringForceRequest, bool>(1, answer, same);
  return {
      model("t1_nan_for_coincident_particles", true,
            "Your spring force behaves exactly like one with no guard for coincident particles: "
            "when l = 0, e = d / l is NaN; return a zero force when l is below a small epsilon.")};
}

}  // namespace a6::grader::mistakes
