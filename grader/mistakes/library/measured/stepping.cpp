// Task 3 measured: one step of a small system with the reference forces (a spring between two
// free particles, a pinned particle, a lone free particle last), split into the velocity update
// (each particle's Δv as the external force and each end of the spring over m, times dt), the
// position update (Δx as the old velocity and the student's own Δv, times dt), the pinned
// particle, the particles the step reaches, a second step (are the forces reset?), and advance's
// substeps (a lone particle's Δv over a frame of n substeps).
#include <algorithm>

#include "mistakes/library/measured/tasks.h"

namespace a6::grader::measured {
namespace {

#include "reference/physics.inc"

using harness::SimulateRequest;

constexpr std::size_t kP1 = 0, kP2 = 1, kPinned = 2, kLone = 3;

SimulateRequest stepRequest(double dt, int frames) {
  SimulateRequest r;
  Particle a, b, pinned, lone;
  a.x = Vec2(0, 1), a.v = Vec2(1, 0.5), a.m = 0.5;
  b.x = Vec2(0.8, 1.2), b.v = Vec2(-0.4, 1.0), b.m = 2;
  pinned.x = Vec2(2, 0), pinned.v = Vec2(0.3, 0.2), pinned.pinned = true;
  lone.x = Vec2(3, 1), lone.v = Vec2(0.6, -0.2), lone.m = 1.3;
  r.particles = {a, b, pinned, lone};
  r.springs = {{0, 1, 0.5, 30, 0.2, SpringType::Other}};
  r.env.drag = 0.1;
  r.frameDt = dt, r.frames = frames, r.stepOnly = true, r.referenceForces = true;
  return r;
}

SimulateRequest advanceRequest(int substeps) {
  SimulateRequest r = stepRequest(1.0 / 60, 1);
  r.particles = {r.particles[kLone]};
  r.springs.clear();
  r.env.drag = 0;
  r.stepOnly = false, r.substeps = substeps;
  return r;
}

// The forces of the physics on each particle of a state: external, the spring's +f on its p2
// end and its -f on its p1 end.
struct Forces {
  std::vector<Vec2> external, onP2, onP1;
};

Forces forcesAt(const std::vector<Particle>& ps, const SimulateRequest& r) {
  Forces f;
  for (const Particle& p : ps) {
    f.external.push_back(referenceExternalForce(p, r.env));
    f.onP2.push_back(Vec2::Zero());
    f.onP1.push_back(Vec2::Zero());
  }
  for (const SpringData& d : r.springs) {
    const Particle &p1 = ps[static_cast<std::size_t>(d.i)], &p2 = ps[static_cast<std::size_t>(d.j)];
    const Vec2 force = referenceSpringTerms(p1, p2, d.restLength, d.ks, d.kd).elastic +
                       referenceSpringTerms(p1, p2, d.restLength, d.ks, d.kd).damping;
    f.onP2[static_cast<std::size_t>(d.j)] += force;
    f.onP1[static_cast<std::size_t>(d.i)] -= force;
  }
  return f;
}

// The student's state after `frame` (1-based) of an answer, if it recorded one that fits.
const std::vector<Particle>* stateAfter(const harness::SimulateResult& a, int frame,
                                        std::size_t count) {
  for (std::size_t k = 0; k < a.recordedFrames.size() && k < a.states.size(); ++k) {
    if (a.recordedFrames[k] == frame && a.states[k].size() == count) return &a.states[k];
  }
  return nullptr;
}

bool untouched(const Particle& before, const Particle& after) {
  return before.x == after.x && before.v == after.v;
}

const char* particleName(std::size_t i) {
  static const char* const kNames[] = {"the spring's p1", "the spring's p2", "the pinned particle",
                                       "the lone particle (the last of 4)"};
  return kNames[i];
}

std::string whereOf(std::size_t i, const Particle& p, double dt) {
  return particleName(i) + std::string(" (m = ") + number(p.m) + "), dt = " + number(dt);
}

Part velocityPart() {
  return {"velocity",
          "velocity update",
          kVelocityStepFormula,
          "m/s",
          false,
          {{"m", false, -1}, {"dt", false, 1}},
          {{"the external force's f/m dt"},
           {"the spring's +f/m dt on its p2"},
           {"the spring's -f/m dt on its p1"}},
          {}};
}

Part pinnedPart() {
  return {"pinned",
          "step of a pinned particle",
          "no change: x and v stay",
          "",
          false,
          {},
          {{"a free particle's velocity change f/m dt", 0}, {"a free particle's move v dt", 0}},
          {}};
}

// The parts of one step (frame 1 of an answer to stepRequest): every free particle's velocity
// and position update, the pinned particle's, and the free particles it left untouched.
struct StepParts {
  Part velocity = velocityPart(), position = positionPart(), pinned = pinnedPart();
  std::vector<std::size_t> untouched;
};

void addFree(StepParts& parts, std::size_t i, const Particle& before, const Particle& after,
             const Forces& f, double dt) {
  const Vec2 dv = after.v - before.v,
             physics = (f.external[i] + f.onP2[i] + f.onP1[i]) / before.m * dt;
  const std::string where = whereOf(i, before, dt);
  parts.velocity.samples.push_back(
      {{before.m, dt},
       physics,
       dv,
       {f.external[i] / before.m * dt, f.onP2[i] / before.m * dt, f.onP1[i] / before.m * dt},
       where});
  parts.position.samples.push_back(
      {{dt}, (before.v + dv) * dt, after.x - before.x, {before.v * dt, dv * dt}, where});
}

void addStep(StepParts& parts, const ExchangeOf<SimulateRequest>& x) {
  const std::vector<Particle>& before = x.request.particles;
  const std::vector<Particle>* after = stateAfter(x.result, 1, before.size());
  if (after == nullptr) return;
  const double dt = x.request.frameDt;
  const Forces f = forcesAt(before, x.request);
  for (std::size_t i = 0; i < before.size(); ++i) {
    const Particle &b = before[i], &a = (*after)[i];
    if (i == kPinned) {
      const Vec2 free = f.external[i] / b.m * dt;
      parts.pinned.samples.push_back(
          {{}, Vec2::Zero(), a.v - b.v, {free, Vec2::Zero()}, "the pinned particle's velocity"});
      parts.pinned.samples.push_back({{},
                                      Vec2::Zero(),
                                      a.x - b.x,
                                      {Vec2::Zero(), a.v * dt},
                                      "the pinned particle's position"});
    } else if (untouched(b, a)) {
      parts.untouched.push_back(i);
    } else {
      addFree(parts, i, b, a, f, dt);
    }
  }
}

// The second step's velocity update (frame 2 of stepRequest(dt, 2)), from the student's own
// first state: this step's forces, and the first step's (kept, never reset) as an alternative.
Part secondStepPart(const Transcript& t) {
  Part part{"second_step",
            "second step's velocity update",
            kVelocityStepFormula,
            "m/s",
            false,
            {},
            {{"this step's forces f/m dt"}, {"the first step's forces f/m dt, kept", 0}},
            {}};
  for (const auto& x : answersTo<SimulateRequest>(t, "t3.step2")) {
    const std::vector<Particle>& start = x.request.particles;
    const auto* one = stateAfter(x.result, 1, start.size());
    const auto* two = stateAfter(x.result, 2, start.size());
    if (one == nullptr || two == nullptr) continue;
    const Forces f1 = forcesAt(start, x.request), f2 = forcesAt(*one, x.request);
    const double dt = x.request.frameDt;
    for (std::size_t i : {kP1, kP2, kLone}) {
      const double m = start[i].m;
      const Vec2 now = (f2.external[i] + f2.onP2[i] + f2.onP1[i]) / m * dt;
      const Vec2 kept = (f1.external[i] + f1.onP2[i] + f1.onP1[i]) / m * dt;
      part.samples.push_back(
          {{}, now, (*two)[i].v - (*one)[i].v, {now, kept}, whereOf(i, start[i], dt)});
    }
  }
  return part;
}

// advance(T, n): the lone particle's velocity change over one frame of n substeps (no drag, so
// it is g T whatever n).
Part advancePart(const Transcript& t) {
  Part part{"advance", "advance", "n steps of dt = T / n", "m/s", false, {{"n (substeps)"}},
            {},        {}};
  for (const auto& x : answersTo<SimulateRequest>(t, "t3.advance")) {
    const auto* after = stateAfter(x.result, 1, 1);
    if (after == nullptr) continue;
    const Particle& p = x.request.particles[0];
    part.samples.push_back({{static_cast<double>(x.request.substeps)},
                            referenceGravity(p, x.request.env) / p.m * x.request.frameDt,
                            (*after)[0].v - p.v,
                            {},
                            "n = " + std::to_string(x.request.substeps) + ", T = 1/60 s"});
  }
  return part;
}

Finding untouchedFinding(const std::vector<std::size_t>& untouched) {
  Finding f;
  f.tag = "loop";
  f.part = "step's loop over the particles";
  if (untouched.empty()) return f.verdict = Verdict::Right, f;
  if (untouched.size() >= 6) return f;  // no free particle moved in either step: a stub
  f.verdict = Verdict::Differs;
  f.key = "untouched";
  f.how = std::string("leaves a free particle unmoved: ") + particleName(untouched.front()) +
          " keeps its x and v";
  f.measured = "particle " + std::to_string(untouched.front() + 1) + " of 4 unchanged";
  return f;
}

// Task 7's step: a pinned anchor and two free particles in a chain, stepped once implicitly.
SimulateRequest implicitRequest(double h, const Vec2& va, const Vec2& vb, const Vec2& xb) {
  SimulateRequest r;
  Particle anchor, a, b;
  anchor.x = Vec2(0, 0), anchor.pinned = true;
  a.x = Vec2(0.1, -0.6), a.v = va, a.m = 0.3;
  b.x = xb, b.v = vb, b.m = 0.5;
  r.particles = {anchor, a, b};
  r.springs = {{0, 1, 0.5, 80, 0.4, SpringType::Other}, {1, 2, 0.5, 60, 0.3, SpringType::Other}};
  r.frameDt = h, r.frames = 1, r.stepOnly = true, r.implicit = true, r.referenceForces = true;
  return r;
}

// The terms of row i of the linearised backward Euler system, moved to one side:
// m Δv_i = h f_i + Σ (h dfdv + h² dfdx)(Δv_i - Δv_j) + h² dfdx (v_j - v_i) (signed by the end),
// each piece on its own, with Δv the student's own (a pinned particle's is 0).
std::vector<Vec2> rowTerms(const SimulateRequest& r, const Forces& f, const std::vector<Vec2>& dv,
                           std::size_t i) {
  const double h = r.frameDt;
  std::vector<Vec2> t(9, Vec2::Zero());
  t[0] = h * (f.external[i] + f.onP2[i] + f.onP1[i]);
  for (const SpringData& d : r.springs) {
    const std::size_t a = static_cast<std::size_t>(d.i), b = static_cast<std::size_t>(d.j);
    if (i != a && i != b) continue;
    const std::size_t other = i == a ? b : a;
    const auto [dfdx, dfdv] =
        referenceSpringJacobians(r.particles[a].x, r.particles[b].x, d.restLength, d.ks, d.kd);
    t[1] += h * dfdv * dv[i], t[2] -= h * dfdv * dv[other];
    t[3] += h * h * dfdx * dv[i], t[4] -= h * h * dfdx * dv[other];
    t[5] += (i == b ? 1.0 : -1.0) * h * h * dfdx * (r.particles[b].v - r.particles[a].v);
    t[6] += h * dfdx * dv[i], t[7] -= h * dfdx * dv[other];
    t[8] += (i == b ? 1.0 : -1.0) * h * dfdx * (r.particles[b].v - r.particles[a].v);
  }
  return t;
}

Part systemPart() {
  return {"system",
          "implicit step's system",
          "(M - h dfdv - h² dfdx) Δv = h (f + h dfdx v)",
          "N·s",
          false,
          {},
          {{"h f"},
           {"h dfdv Δv_i"},
           {"the neighbour's -h dfdv Δv_j (an off-diagonal block)"},
           {"h² dfdx Δv_i"},
           {"the neighbour's -h² dfdx Δv_j (an off-diagonal block)"},
           {"h² dfdx (v_j - v_i) in b (the right-hand side)"},
           {"h dfdx Δv_i", 0, 3},
           {"the neighbour's -h dfdx Δv_j", 0, 4},
           {"h dfdx (v_j - v_i) in b", 0, 5}},
          {}};
}

// Each free particle's row of the system (m Δv against its terms) and its position update.
void addImplicit(Part& system, Part& position, const ExchangeOf<SimulateRequest>& x) {
  const std::vector<Particle>& before = x.request.particles;
  const std::vector<Particle>* after = stateAfter(x.result, 1, before.size());
  if (after == nullptr) return;
  std::vector<Vec2> dv;
  for (std::size_t i = 0; i < before.size(); ++i)
    dv.push_back(before[i].pinned ? Vec2::Zero() : Vec2((*after)[i].v - before[i].v));
  const Forces f = forcesAt(before, x.request);
  const double h = x.request.frameDt;
  for (std::size_t i = 1; i < before.size(); ++i) {
    const std::string where = std::string(i == 1 ? "the middle particle" : "the end particle") +
                              " (m = " + number(before[i].m) + "), h = " + number(h);
    Sample s{{}, Vec2::Zero(), before[i].m * dv[i], rowTerms(x.request, f, dv, i), where};
    for (std::size_t j = 0; j < 6; ++j) s.physics += s.terms[j];
    system.samples.push_back(std::move(s));
    position.samples.push_back({{h},
                                (before[i].v + dv[i]) * h,
                                (*after)[i].x - before[i].x,
                                {before[i].v * h, dv[i] * h},
                                where});
  }
}

}  // namespace

void designImplicit(std::vector<Designed>& out) {
  out.push_back(designed(
      "t7.step", implicitRequest(1.0 / 60, Vec2(0.5, 0.2), Vec2(-0.3, 0.4), Vec2(0.3, -1.3))));
  out.push_back(designed(
      "t7.step", implicitRequest(1.0 / 30, Vec2(-0.2, 0.7), Vec2(0.6, 0.1), Vec2(0.5, -1.1))));
  out.push_back(designed(
      "t7.step", implicitRequest(1.0 / 45, Vec2(0.9, -0.3), Vec2(0.2, -0.8), Vec2(-0.2, -1.2))));
  out.push_back(
      designed("t7.step", implicitRequest(1.0 / 20, Vec2(0, 0), Vec2(1.1, 0.5), Vec2(0.4, -1.4))));
}

std::vector<Finding> measureImplicit(const Transcript& t) {
  Part system = systemPart(), position = positionPart();
  for (const auto& x : answersTo<SimulateRequest>(t, "t7.step")) addImplicit(system, position, x);
  Finding solved = measure(system);
  if (solved.verdict != Verdict::Right) return {solved};  // the positions follow a wrong Δv
  return {solved, measure(position)};
}

void designStepping(std::vector<Designed>& out) {
  out.push_back(designed("t3.step", stepRequest(1.0 / 60, 1)));
  out.push_back(designed("t3.step", stepRequest(1.0 / 30, 1)));
  out.push_back(designed("t3.step2", stepRequest(1.0 / 60, 2)));
  for (int n = 1; n <= 4; ++n) out.push_back(designed("t3.advance", advanceRequest(n)));
}

std::vector<Finding> measureStepping(const Transcript& t) {
  StepParts parts;
  for (const auto& x : answersTo<SimulateRequest>(t, "t3.step")) addStep(parts, x);
  std::vector<Finding> f = {measure(parts.velocity), measure(parts.position), measure(parts.pinned),
                            untouchedFinding(parts.untouched)};
  // Each later part means something only where the step before it is right: a second step
  // after a right first one, advance's frame of steps after right steps.
  const auto right = [&f] {
    return std::all_of(f.begin(), f.end(), [](const Finding& x) {
      return x.verdict == Verdict::Right || x.verdict == Verdict::Unmeasured;
    });
  };
  if (right()) f.push_back(measure(secondStepPart(t)));
  if (right()) f.push_back(measure(advancePart(t)));
  return f;
}

Part positionPart() {
  return {"position",
          "position update",
          "x += v dt with the new v",
          "m",
          false,
          {{"dt", false, 1}},
          {{"the old velocity's v dt"}, {"the step's Δv dt (x moves with the new v)"}},
          {}};
}

}  // namespace a6::grader::measured
