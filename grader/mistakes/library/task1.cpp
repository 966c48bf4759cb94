// Task 1, the spring force: the reference f2 = -ks (l - l0) e - kd ((v2 - v1)·e) e, and the
// catalogue's mistake of the guard for coincident particles (tests/wrong/t1_nan_*). The terms'
// mistakes are named part by part (parts.cpp).
#include <optional>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"

namespace a6::grader::mistakes {
namespace {

using harness::SpringForceRequest;

Vec2 springForce(const SpringForceRequest& r, bool guarded) {
  const Vec2 d = r.p2.x - r.p1.x;
  const double l = d.norm();
  if (l < 1e-12 && guarded) return Vec2::Zero();
  const Vec2 e = d / l;
  return -r.ks * (l - r.restLength) * e - r.kd * (r.p2.v - r.p1.v).dot(e) * e;
}

// The answer as the checks get it, with or without (`unguarded`) the guard.
std::optional<harness::SpringForceResult> answer(const SpringForceRequest& r, bool unguarded) {
  harness::SpringForceResult out;
  out.force = springForce(r, !unguarded);
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
