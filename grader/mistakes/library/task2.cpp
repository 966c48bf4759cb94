// Task 2, the forces, named part by part (as parts.cpp names the spring force's terms): gravity
// m g, buoyancy b (T - T_air) (0, 1), drag -k_d v, repulsion k_r d n while inside, and
// externalForce, their sum with the repulsion of every obstacle. Each part has the physics' form
// and the wrong forms students write (tests/wrong/t2_*, b2_*, c2_*); every combination of one or
// two wrong parts is a model, named only when it alone of task 2's fits every answer.
#include <array>
#include <string>
#include <vector>

#include "mistakes/library/compare.h"
#include "mistakes/library/models.h"

namespace a6::grader::mistakes {
namespace {

#include "reference/physics.inc"

using harness::ForcesRequest;
using harness::ForcesResult;

// One form of one part: its key (for the model's id), how it differs from the physics (for the
// student's sentence) and its formula. The first form of each part is the physics'.
struct Form {
  const char* key;
  const char* how;
  const char* formula;
};

enum Part { kGravity, kBuoyancy, kDrag, kRepulsion, kSum, kParts };

const char* const kPartNames[kParts] = {"gravity", "buoyancy", "drag", "repulsion",
                                        "externalForce"};

const std::vector<Form>& formsOf(int part) {
  static const std::vector<Form> forms[kParts] = {
      {{"", "", kGravityFormula},
       {"gravity_without_mass", "leaves out the mass", "g"},
       {"gravity_sign", "has the wrong sign", "-m g"}},
      {{"", "", kBuoyancyFormula},
       {"buoyancy_downwards", "has the wrong sign", "b (T_air - T) (0, 1)"},
       {"buoyancy_no_air", "leaves out the air's temperature", "b T (0, 1)"}},
      {{"", "", kDragFormula},
       {"drag_wrong_sign", "has the wrong sign", "+k_d v"},
       {"drag_quadratic", "grows with the square of the speed", "-k_d |v| v"}},
      {{"", "", "k_r d n while d > 0, else 0"},
       {"repulsion_always_on", "has no depth check: outside an obstacle it pulls the particle in",
        "k_r d n for every d"},
       {"repulsion_sign", "has the wrong sign", "-k_r d n while d > 0"}},
      {{"", "", "the forces plus every obstacle's k_r d n"},
       {"external_forgets_circles", "forgets the circles",
        "the forces plus the half-planes' k_r d n only"},
       {"external_stops_at_first_obstacle", "stops at the first obstacle that pushes",
        "the forces plus the first pushing obstacle's k_r d n"},
       {"external_repulsion_uses_kd", "hands repulsionForce the drag coefficient k_d, not k_r",
        "the forces plus every obstacle's k_d d n"}},
  };
  return forms[part];
}

// The forms of each part, in the order of formsOf's lists (the physics' first).
enum Gravity : std::size_t { kMassTimesG, kGravityNoMass, kGravitySign };
enum Buoyancy : std::size_t { kWarmerRises, kBuoyancySign, kBuoyancyNoAir };
enum Drag : std::size_t { kLinearDrag, kDragSign, kDragQuadratic };
enum Repulsion : std::size_t { kWhileInside, kRepulsionAlwaysOn, kRepulsionSign };
enum Sum : std::size_t { kEveryObstacle, kSumNoCircles, kSumFirstObstacle, kSumWithDrag };

// The form of each part a model takes.
using Choice = std::array<std::size_t, kParts>;

// A part's value in its form: the physics' (the reference's) or a wrong one.
Vec2 repulsion(const Contact& c, double kr, std::size_t form) {
  if (form == kRepulsionAlwaysOn) return kr * c.depth * c.normal;
  const Vec2 f = referenceRepulsion(kr, c);
  return form == kRepulsionSign ? Vec2(-f) : f;
}

Vec2 gravity(const Particle& p, const Environment& env, std::size_t form) {
  if (form == kGravityNoMass) return env.gravity;
  const Vec2 f = referenceGravity(p, env);
  return form == kGravitySign ? Vec2(-f) : f;
}

Vec2 buoyancy(const Particle& p, const Environment& env, std::size_t form) {
  if (form == kBuoyancySign)
    return env.buoyancy * (env.airTemperature - p.temperature) * Vec2(0, 1);
  if (form == kBuoyancyNoAir) return env.buoyancy * p.temperature * Vec2(0, 1);
  return referenceBuoyancy(p, env);
}

Vec2 drag(const Particle& p, const Environment& env, std::size_t form) {
  const Vec2 f = referenceDrag(p, env);
  if (form == kDragSign) return -f;
  return form == kDragQuadratic ? Vec2(-env.drag * p.v.norm() * p.v) : f;
}

// externalForce's sum in its form: the three forces, then each obstacle's repulsion (the
// half-planes first, as the handout's loop takes them).
Vec2 sum(const ForcesRequest& r, const ForcesResult& parts, const Choice& c) {
  const double kr = c[kSum] == kSumWithDrag ? r.env.drag : r.env.repulsion;
  Vec2 f = parts.gravity + parts.buoyancy + parts.drag;
  std::vector<Contact> contacts;
  for (const HalfPlane& plane : r.env.planes) contacts.push_back(contactWith(plane, r.particle.x));
  if (c[kSum] != kSumNoCircles) {
    for (const CircleObstacle& circle : r.env.circles)
      contacts.push_back(contactWith(circle, r.particle.x));
  }
  for (const Contact& contact : contacts) {
    const Vec2 push = repulsion(contact, kr, c[kRepulsion]);
    f += push;
    if (c[kSum] == kSumFirstObstacle && push != Vec2::Zero()) break;
  }
  return f;
}

ForcesResult forces(const ForcesRequest& r, const Choice& c) {
  ForcesResult out;
  out.gravity = gravity(r.particle, r.env, c[kGravity]);
  out.buoyancy = buoyancy(r.particle, r.env, c[kBuoyancy]);
  out.drag = drag(r.particle, r.env, c[kDrag]);
  out.repulsion = repulsion(r.contact, r.env.repulsion, c[kRepulsion]);
  out.total = sum(r, out, c);
  return out;
}

bool same(const ForcesResult& a, const ForcesResult& b) {
  return near(a.gravity, b.gravity) && near(a.buoyancy, b.buoyancy) && near(a.drag, b.drag) &&
         near(a.repulsion, b.repulsion) && near(a.total, b.total);
}

bool isZero(const ForcesResult& a) {
  return a.gravity == Vec2::Zero() && a.buoyancy == Vec2::Zero() && a.drag == Vec2::Zero() &&
         a.repulsion == Vec2::Zero() && a.total == Vec2::Zero();
}

// The id ("t2_drag_wrong_sign", "t2_gravity_sign_and_drag_quadratic") and the sentence of a
// combination: "Your drag has the wrong sign: yours is +k_d v, the physics gives -k_d v (...)".
MistakeModel describe(const Choice& c) {
  std::string id = "t2", text;
  for (int part = 0; part < kParts; ++part) {
    if (c[part] == 0) continue;
    const Form& yours = formsOf(part)[c[part]];
    const bool first = text.empty();
    id += std::string(first ? "_" : "_and_") + yours.key;
    text += std::string(first ? "Your " : "; your ") + kPartNames[part] + " " + yours.how +
            ": yours is " + yours.formula + ", the physics gives " + formsOf(part)[0].formula;
  }
  MistakeModel m{id, 2, text + " (the other parts are right).", nullptr};
  m.partByPart = true;
  return m;
}

MistakeModel model(const Choice& c) {
  MistakeModel m = describe(c);
  m.judge = [c](const Transcript& t) {
    std::vector<Likeness> out;
    if (allZero<ForcesRequest>(t, isZero)) return out;
    for (const auto& x : t.of<ForcesRequest>()) {
      out.push_back(likeness(x.result, forces(x.request, Choice{}), forces(x.request, c), same));
    }
    return out;
  };
  return m;
}

}  // namespace

std::vector<MistakeModel> task2Mistakes() {
  std::vector<MistakeModel> models;
  // One wrong part, then every pair of wrong parts, in the parts' order.
  for (int a = 0; a < kParts; ++a) {
    for (std::size_t i = 1; i < formsOf(a).size(); ++i) {
      Choice c{};
      c[a] = i;
      models.push_back(model(c));
      for (int b = a + 1; b < kParts; ++b) {
        for (std::size_t j = 1; j < formsOf(b).size(); ++j) {
          Choice both = c;
          both[b] = j;
          models.push_back(model(both));
        }
      }
    }
  }
  return models;
}

}  // namespace a6::grader::mistakes
