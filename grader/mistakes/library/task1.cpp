// Task 1, the spring force: the reference f2 = -ks (l - l0) e - kd ((v2 - v1)·e) e, and the
// mistakes of tests/wrong/t1_*, each answering SpringForceRequest as that wrong version does.
#include <optional>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"

namespace a6::grader::mistakes {
namespace {

using harness::SpringForceRequest;

enum class Flaw { None, WrongSign, DampingFullVelocity, DampingV2Only, NoCoincidentGuard };

Vec2 springForce(const SpringForceRequest& r, Flaw flaw) {
  const Vec2 d = r.p2.x - r.p1.x;
  const double l = d.norm();
  if (l < 1e-12 && flaw != Flaw::NoCoincidentGuard) return Vec2::Zero();
  const Vec2 e = d / l;
  const Vec2 relative = r.p2.v - r.p1.v;
  const double stretch = r.ks * (l - r.restLength);
  switch (flaw) {
    case Flaw::WrongSign:
      return stretch * e - r.kd * relative.dot(e) * e;
    case Flaw::DampingFullVelocity:
      return -stretch * e - r.kd * relative;
    case Flaw::DampingV2Only:
      return -stretch * e - r.kd * r.p2.v.dot(e) * e;
    default:
      return -stretch * e - r.kd * relative.dot(e) * e;
  }
}

// The answer as the checks get it.
std::optional<harness::SpringForceResult> answer(const SpringForceRequest& r, Flaw flaw) {
  harness::SpringForceResult out;
  out.force = springForce(r, flaw);
  return out;
}

bool same(const harness::SpringForceResult& a, const harness::SpringForceResult& b) {
  return near(a.force, b.force);
}

MistakeModel model(const char* id, Flaw flaw, const char* text) {
  auto judge = [flaw](const Transcript& t) {
    return judgeEach(
        t.springs, [](const SpringForceRequest& r) { return answer(r, Flaw::None); },
        [flaw](const SpringForceRequest& r) { return answer(r, flaw); }, same);
  };
  return MistakeModel{id, 1, text, judge};
}

}  // namespace

std::vector<MistakeModel> task1Mistakes() {
  return {
      model("t1_wrong_sign", Flaw::WrongSign,
            "Your spring force behaves exactly like one whose spring term has the wrong sign, "
            "+ks (l - l0) e: a stretched spring pushes p2 away instead of pulling it back; the "
            "force on p2 is -ks (l - l0) e."),
      model("t1_damping_full_relative_velocity", Flaw::DampingFullVelocity,
            "Your spring force behaves exactly like one whose damping uses the full relative "
            "velocity v2 - v1 instead of its component along the spring: project it on e first, "
            "-kd ((v2 - v1)·e) e."),
      model("t1_damping_uses_v2_only", Flaw::DampingV2Only,
            "Your spring force behaves exactly like one whose damping uses p2's velocity alone, "
            "v2·e, instead of the relative velocity (v2 - v1)·e: a spring that moves as a whole "
            "must not be damped."),
      model("t1_nan_for_coincident_particles", Flaw::NoCoincidentGuard,
            "Your spring force behaves exactly like one with no guard for coincident particles: "
            "when l = 0, e = d / l is NaN; return a zero force when l is below a small epsilon."),
  };
}

}  // namespace a6::grader::mistakes
