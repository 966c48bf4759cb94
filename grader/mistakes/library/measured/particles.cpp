// Task 5 measured: one update of three particles already alive (no emission, the reference
// forces), set beside the reference update particle by particle (matched by their lifetimes,
// each its own, so any order of the list is fine): the velocity and position updates, cooling,
// ageing and removal (the third particle's age reaches its lifetime in this update). And one
// update that emits a particle into an empty system: the slide's update emits first, then moves
// and ages every particle, so the newborn is dt old after it.
#include <algorithm>
#include <cmath>

#include "mistakes/library/measured/tasks.h"
#include "reference/steppers.h"

namespace a6::grader::measured {
namespace {

#include "reference/physics.inc"

using harness::ParticleRunRequest;

ParticleRunRequest aliveRequest(double dt, double cooling) {
  ParticleRunRequest r;
  r.emitter.rate = 0;
  r.env.drag = 0.05, r.env.buoyancy = 0.002, r.env.airTemperature = 293.15;
  r.coolingRate = cooling, r.dt = dt, r.steps = 1, r.referenceForces = true;
  const Vec2 xs[] = {Vec2(0, 0), Vec2(1, 0.5), Vec2(2, -0.5)};
  const Vec2 vs[] = {Vec2(0.5, 1), Vec2(-0.3, 2), Vec2(0.1, 0.4)};
  const double ts[] = {600, 900, 350}, ages[] = {0.2, 0.5, 0.995}, lifetimes[] = {1.5, 2, 1};
  for (int i = 0; i < 3; ++i) {
    Particle p;
    p.x = xs[i], p.v = vs[i], p.m = 0.01 * (i + 1), p.temperature = ts[i];
    p.age = ages[i], p.lifetime = lifetimes[i];
    r.initial.push_back(p);
  }
  return r;
}

ParticleRunRequest emitRequest() {
  ParticleRunRequest r = aliveRequest(1.0 / 60, 0.8);
  r.initial.clear();
  r.emitter.rate = 60;  // one particle in a step of 1/60 s
  r.emitter.lifetimeMin = 5, r.emitter.lifetimeMax = 6;
  return r;
}

// The particle of `list` that is `p` after the update: the one of its lifetime (each initial
// particle has its own, and an update never changes it), whatever the list's order and however
// far a wrong update moved it.
const Particle* after(const std::vector<Particle>& list, const Particle& p) {
  for (const Particle& q : list) {
    if (q.lifetime == p.lifetime) return &q;
  }
  return nullptr;
}

struct UpdateParts {
  Part velocity{"velocity",
                "velocity update",
                kVelocityStepFormula,
                "m/s",
                false,
                {{"m", false, -1}, {"dt", false, 1}},
                {{"f/m dt"}},
                {}};
  Part position = positionPart();
  Part cooling{"cooling",
               "cooling",
               kCoolingFormula,
               "K",
               true,
               {{"k_c", true, 1}, {"dt", false, 1}, {"|T - T_air|", false, 1}},
               {{"-k_c T dt"}, {"k_c T_air dt"}},
               {}};
  Part ageing{"ageing", "ageing", "age += dt", "s", true, {{"dt", false, 1}}, {{"dt"}}, {}};
  std::vector<std::string> kept, removed;  // the particles removed wrongly or kept wrongly
};

void addParticle(UpdateParts& u, const ParticleRunRequest& r, const Particle& before,
                 const Particle& after, const std::string& where) {
  const double dt = r.dt;
  const Vec2 f = referenceExternalForce(before, r.env), dv = after.v - before.v;
  u.velocity.samples.push_back({{before.m, dt}, f / before.m * dt, dv, {f / before.m * dt}, where});
  u.position.samples.push_back(
      {{dt}, (before.v + dv) * dt, after.x - before.x, {before.v * dt, dv * dt}, where});
  const double hot = before.temperature - r.env.airTemperature;
  u.cooling.samples.push_back(
      {{r.coolingRate, dt, std::abs(hot)},
       Vec2(referenceCooling(before, r.env, r.coolingRate, dt), 0),
       Vec2(after.temperature - before.temperature, 0),
       {Vec2(-r.coolingRate * before.temperature * dt, 0),
        Vec2(r.coolingRate * r.env.airTemperature * dt, 0)},
       where + ", k_c = " + number(r.coolingRate) + ", T = " + number(before.temperature)});
  u.ageing.samples.push_back(
      {{dt}, Vec2(dt, 0), Vec2(after.age - before.age, 0), {Vec2(dt, 0)}, where});
}

void addUpdate(UpdateParts& u, const ExchangeOf<ParticleRunRequest>& x) {
  const std::optional<harness::ParticlesResult> physics =
      reference::runParticles(x.request, reference::ParticleFlaw::None);
  if (!physics) return;
  for (std::size_t i = 0; i < x.request.initial.size(); ++i) {
    const Particle& before = x.request.initial[i];
    const Particle* yours = after(x.result.particles, before);
    const bool alive = after(physics->particles, before) != nullptr;
    const std::string where = "particle " + std::to_string(i + 1) + " (age " + number(before.age) +
                              " of " + number(before.lifetime) +
                              " s), dt = " + number(x.request.dt);
    if (yours != nullptr && !alive) u.kept.push_back(where);
    if (yours == nullptr && alive) u.removed.push_back(where);
    if (yours != nullptr && alive) addParticle(u, x.request, before, *yours, where);
  }
}

Finding removalFinding(const UpdateParts& u) {
  Finding f;
  f.tag = "removal", f.part = "removal of old particles";
  f.verdict = u.kept.empty() && u.removed.empty() ? Verdict::Right : Verdict::Differs;
  if (!u.kept.empty())
    f.how = "keeps a particle whose age reaches its lifetime in this update (" + u.kept.front() +
            "): the slide's update removes it in the same update, after ageing it";
  else if (!u.removed.empty())
    f.how = "removes a particle before its age reaches its lifetime (" + u.removed.front() + ")";
  return f;
}

// The emitting update: the newborn's age after it (dt: emitted first, then aged).
Finding emissionFinding(const Transcript& t) {
  Finding f;
  f.tag = "emission", f.part = "emission in update";
  for (const auto& x : answersTo<ParticleRunRequest>(t, "t5.emit")) {
    if (x.result.particles.size() != 1) return f;  // a stub emits nothing: unmeasured
    const double age = x.result.particles[0].age, dt = x.request.dt;
    f.measured = "a newborn's age after its first update is " + number(age) + " s, the " +
                 "physics' " + number(dt) + " s";
    if (std::abs(age - dt) <= 1e-6 * dt) return f.verdict = Verdict::Right, f;
    f.verdict = age == 0 ? Verdict::Differs : Verdict::Unexplained;
    f.how =
        "comes after the particles are moved and aged: a newborn is still 0 s old after its "
        "first update (the slide emits first, then moves and ages every particle)";
  }
  return f;
}

}  // namespace

void designParticles(std::vector<Designed>& out) {
  out.push_back(designed("t5.update", aliveRequest(1.0 / 60, 0.8)));
  out.push_back(designed("t5.update", aliveRequest(1.0 / 30, 0.8)));
  out.push_back(designed("t5.update", aliveRequest(1.0 / 60, 1.6)));
  out.push_back(designed("t5.emit", emitRequest()));
}

std::vector<Finding> measureParticles(const Transcript& t) {
  UpdateParts u;
  for (const auto& x : answersTo<ParticleRunRequest>(t, "t5.update")) addUpdate(u, x);
  std::vector<Finding> f = {measure(u.velocity), measure(u.position), measure(u.cooling),
                            measure(u.ageing)};
  // An update that changes no particle is a stub's: its removal and emission tell nothing.
  if (std::all_of(f.begin(), f.end(), [](const Finding& x) { return x.zero; })) return {};
  f.push_back(removalFinding(u));
  f.push_back(emissionFinding(t));
  return f;
}

}  // namespace a6::grader::measured
