// Task 2, the forces: the reference gravity m g, buoyancy b (T - T_air)(0,1), drag -k_d v,
// repulsion k_r d n while inside and their sum over every obstacle, and the mistakes of
// tests/wrong/t2_*, each answering ForcesRequest as that wrong version does.
#include <optional>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"

namespace a6::grader::mistakes {
namespace {

using harness::ForcesRequest;
using harness::ForcesResult;

enum class Flaw {
  None,
  BuoyancyDown,
  DragWrongSign,
  ForgetsCircles,
  GravityWithoutMass,
  AlwaysRepel
};

Vec2 repulsion(const Contact& c, double kr, Flaw flaw) {
  if (c.depth <= 0 && flaw != Flaw::AlwaysRepel) return Vec2::Zero();
  return kr * c.depth * c.normal;
}

Vec2 externalTotal(const ForcesRequest& r, const ForcesResult& parts, Flaw flaw) {
  Vec2 f = parts.gravity + parts.buoyancy + parts.drag;
  for (const HalfPlane& plane : r.env.planes)
    f += repulsion(contactWith(plane, r.particle.x), r.env.repulsion, flaw);
  if (flaw == Flaw::ForgetsCircles) return f;
  for (const CircleObstacle& circle : r.env.circles)
    f += repulsion(contactWith(circle, r.particle.x), r.env.repulsion, flaw);
  return f;
}

// The answer of the forces with `flaw` (never empty: every request can be answered).
std::optional<ForcesResult> forces(const ForcesRequest& r, Flaw flaw) {
  const Particle& p = r.particle;
  const Environment& env = r.env;
  ForcesResult out;
  out.gravity = flaw == Flaw::GravityWithoutMass ? env.gravity : Vec2(p.m * env.gravity);
  const double warmer = flaw == Flaw::BuoyancyDown ? env.airTemperature - p.temperature
                                                   : p.temperature - env.airTemperature;
  out.buoyancy = env.buoyancy * warmer * Vec2(0, 1);
  out.drag = (flaw == Flaw::DragWrongSign ? env.drag : -env.drag) * p.v;
  out.repulsion = repulsion(r.contact, env.repulsion, flaw);
  out.total = externalTotal(r, out, flaw);
  return out;
}

bool same(const ForcesResult& a, const ForcesResult& b) {
  return near(a.gravity, b.gravity) && near(a.buoyancy, b.buoyancy) && near(a.drag, b.drag) &&
         near(a.repulsion, b.repulsion) && near(a.total, b.total);
}

}  // namespace

std::vector<MistakeModel> task2Mistakes() {
  const auto model = flawModels<ForcesRequest, Flaw>(2, forces, same);
  return {
      model("t2_gravity_without_mass", Flaw::GravityWithoutMass,
            "Your gravity behaves exactly like g without the mass: every particle weighs as if "
            "it had 1 kg; the force is m g."),
      model("t2_buoyancy_downwards", Flaw::BuoyancyDown,
            "Your buoyancy behaves exactly like b (T_air - T)(0, 1): hot particles sink and cold "
            "ones rise; the force is b (T - T_air)(0, 1)."),
      model("t2_drag_wrong_sign", Flaw::DragWrongSign,
            "Your drag behaves exactly like +k_d v: it speeds the particle up; drag opposes the "
            "velocity, -k_d v."),
      model("t2_repulsion_always_on", Flaw::AlwaysRepel,
            "Your repulsion behaves exactly like k_r d n with no depth check: outside an obstacle "
            "the depth is negative and the force pulls the particle in; return zero unless d > 0."),
      model("t2_external_forgets_circles", Flaw::ForgetsCircles,
            "Your externalForce behaves exactly like one that adds the half-planes' repulsion but "
            "forgets the circles: add repulsionForce(contactWith(circle, p.x), k_r) for every "
            "circle too."),
  };
}

}  // namespace a6::grader::mistakes
