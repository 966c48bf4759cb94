#include "checks/divergence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/limits.h"
#include "harness/tasks.h"

namespace a6::grader {
namespace {

std::string vec(const Vec2& v) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.6g, %.6g)", v.x(), v.y());
  return text;
}

std::string num(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// The size positions and velocities are compared against: the largest in the reference's states.
double scaleOf(const std::vector<std::vector<Particle>>& states) {
  double scale = 1;
  for (const auto& state : states) {
    for (const Particle& p : state) scale = std::max({scale, p.x.norm(), p.v.norm()});
  }
  return scale;
}

// How far apart a step's answer may be from the reference's, relative to the states' size: the
// checks' tolerance for one computation (1e-5 of the size); a run is taken as failed beyond the
// tolerance of many steps (1e-4).
constexpr double kStepTolerance = 1e-5;
constexpr double kRunTolerance = 1e-4;

bool apart(const Vec2& a, const Vec2& b, double tolerance) {
  return !((a - b).norm() <= tolerance);
}

// The first quantity in which `yours` departs from `physics` ("particle 2's velocity: yours
// (...), the physics' (...)"), or "" when none does. Particles in the same order.
std::string departure(const std::vector<Particle>& yours, const std::vector<Particle>& physics,
                      double scale, bool particleSystem, double relative = kStepTolerance) {
  const double tolerance = relative * scale;
  if (yours.size() != physics.size())
    return "the count of particles: yours " + std::to_string(yours.size()) + ", the physics' " +
           std::to_string(physics.size());
  for (std::size_t i = 0; i < physics.size(); ++i) {
    const Particle &a = yours[i], &b = physics[i];
    const std::string who = "particle " + std::to_string(i) + "'s ";
    if (apart(a.v, b.v, tolerance))  // the step's first update: a wrong one shows in x too
      return who + "velocity: yours " + vec(a.v) + ", the physics' " + vec(b.v);
    if (apart(a.x, b.x, tolerance))
      return who + "position: yours " + vec(a.x) + ", the physics' " + vec(b.x);
    if (!particleSystem) continue;
    if (!(std::abs(a.temperature - b.temperature) <= relative * std::abs(b.temperature) + 1e-9))
      return who + "temperature: yours " + num(a.temperature) + " K, the physics' " +
             num(b.temperature) + " K";
    if (!(std::abs(a.age - b.age) <= relative * (1 + b.age)))
      return who + "age: yours " + num(a.age) + " s, the physics' " + num(b.age) + " s";
  }
  return "";
}

// A state to restart from: the reference's, without the forces its stepper left in each
// particle (a correct step that adds to p.f and clears it after would otherwise depart).
std::vector<Particle> restart(std::vector<Particle> state) {
  for (Particle& p : state) p.f = Vec2::Zero();
  return state;
}

// A particle system's particles in an order that does not depend on how it removes them.
std::vector<Particle> byPlace(std::vector<Particle> ps) {
  const auto key = [](double v) {  // a NaN sorts last, as the largest
    return std::isnan(v) ? std::numeric_limits<double>::infinity() : v;
  };
  std::sort(ps.begin(), ps.end(), [&key](const Particle& a, const Particle& b) {
    return key(a.x.x()) != key(b.x.x()) ? key(a.x.x()) < key(b.x.x()) : key(a.x.y()) < key(b.x.y());
  });
  return ps;
}

Divergence found(const std::string& check, int step, int steps, const std::string& what,
                 const char* unit) {
  const std::size_t colon = what.find(':');
  return {check, step, steps, what.substr(0, colon),
          "Started from the physics' state before each " + std::string(unit) + ", your code " +
              "first departs at " + unit + " " + std::to_string(step) + " of " +
              std::to_string(steps) + ": " + what + "."};
}

Divergence none(const std::string& check, int steps, const char* unit) {
  return {check, 0, steps, "",
          "Started from the physics' state before each " + std::string(unit) + ", your code's " +
              unit + " matches the physics' every time (" + std::to_string(steps) +
              " of them): your run departs only through what it carries from one " + unit +
              " to the next (forces left from the last one, a counter, a cached value)."};
}

// The check's first run of the stepper the reference can run whose answer is not the reference's.
const harness::SimulateRequest* failedSimulation(const Transcript& t, const std::string& check,
                                                 const ReferenceSteppers& reference) {
  for (const auto& x : t.of<harness::SimulateRequest>()) {
    if (x.check != check || !x.request.referenceForces || x.request.particles.size() > 200)
      continue;
    const std::optional<harness::SimulateResult> physics = reference.simulate(x.request);
    if (!physics) continue;
    if (physics->states.size() != x.result.states.size()) return &x.request;
    for (std::size_t k = 0; k < physics->states.size(); ++k) {
      if (!departure(x.result.states[k], physics->states[k], scaleOf(physics->states), false,
                     kRunTolerance)
               .empty())
        return &x.request;
    }
  }
  return nullptr;
}

Divergence simulationDivergence(BudgetedStudent& student, const std::string& check,
                                const harness::SimulateRequest& request,
                                const ReferenceSteppers& reference) {
  harness::SimulateRequest all = request;
  all.recordEvery = 1;
  all.frames = std::min(request.frames, kDivergenceSteps);
  const std::optional<harness::SimulateResult> physics = reference.simulate(all);
  const char* unit = request.stepOnly || request.substeps <= 1 ? "step" : "frame";
  if (!physics || static_cast<int>(physics->states.size()) != all.frames) return {};
  const double scale = scaleOf(physics->states);
  std::vector<Particle> from = request.particles;
  for (int k = 0; k < all.frames; ++k) {
    harness::SimulateRequest one = all;
    one.particles = from, one.frames = 1;
    const harness::SimulateResult yours = student.ask(one);
    if (!yours.ok())
      return found(check, k + 1, all.frames, "your code failed: " + yours.error, unit);
    const std::string what =
        departure(yours.states.empty() ? std::vector<Particle>{} : yours.states.front(),
                  physics->states[static_cast<std::size_t>(k)], scale, false);
    if (!what.empty()) return found(check, k + 1, all.frames, what, unit);
    from = restart(physics->states[static_cast<std::size_t>(k)]);
  }
  return none(check, all.frames, unit);
}

// The check's first run of particles already alive whose answer is not the reference's.
const harness::ParticleRunRequest* failedParticleRun(const Transcript& t, const std::string& check,
                                                     const ReferenceSteppers& reference) {
  for (const auto& x : t.of<harness::ParticleRunRequest>()) {
    if (x.check != check || x.request.emitter.rate != 0 || !x.request.referenceForces ||
        x.request.initial.size() > 200)
      continue;
    const std::optional<harness::ParticlesResult> physics = reference.particles(x.request);
    if (physics && !departure(byPlace(x.result.particles), byPlace(physics->particles),
                              scaleOf({physics->particles}), true, kRunTolerance)
                        .empty())
      return &x.request;
  }
  return nullptr;
}

Divergence particleDivergence(BudgetedStudent& student, const std::string& check,
                              const harness::ParticleRunRequest& request,
                              const ReferenceSteppers& reference) {
  const int steps = std::min(request.steps, kDivergenceSteps);
  std::vector<Particle> from = request.initial;
  for (int k = 0; k < steps; ++k) {
    harness::ParticleRunRequest one = request;
    one.initial = from, one.steps = 1;
    const std::optional<harness::ParticlesResult> physics = reference.particles(one);
    if (!physics) return {};
    const harness::ParticlesResult yours = student.ask(one);
    if (!yours.ok())
      return found(check, k + 1, steps, "your code failed: " + yours.error, "update");
    const std::string what = departure(byPlace(yours.particles), byPlace(physics->particles),
                                       scaleOf({from, physics->particles}), true);
    if (!what.empty()) return found(check, k + 1, steps, what, "update");
    from = restart(physics->particles);
  }
  return none(check, steps, "update");
}

}  // namespace

std::vector<Divergence> findDivergences(BudgetedStudent& student, const Transcript& transcript,
                                        const std::vector<std::string>& failed,
                                        const ReferenceSteppers& reference) {
  std::vector<Divergence> out;
  if (!reference.simulate || !reference.particles) return out;
  for (const std::string& check : failed) {
    if (out.size() >= kDivergenceChecks) break;
    student.startTest(kReplaySeconds);
    Divergence d;
    if (courseTasks().isPhysicsCheckOf(check, "time_stepping.cpp") ||
        courseTasks().isPhysicsCheckOf(check, "implicit.cpp")) {
      if (const harness::SimulateRequest* r = failedSimulation(transcript, check, reference))
        d = simulationDivergence(student, check, *r, reference);
    } else if (courseTasks().isPhysicsCheckOf(check, "particle_system.cpp")) {
      if (const harness::ParticleRunRequest* r = failedParticleRun(transcript, check, reference))
        d = particleDivergence(student, check, *r, reference);
    }
    if (!d.check.empty()) out.push_back(std::move(d));
  }
  return out;
}

}  // namespace a6::grader
