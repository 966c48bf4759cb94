// Task 2 measured: gravity, buoyancy, drag and repulsion each on its own (every answer carries
// all four), and externalForce as a weighted sum of the student's own four: "your externalForce
// leaves out buoyancy" is its weights 1, 0, 1, 1.
//
// The parts' inputs change one variable at a time around one particle with no obstacle. The
// sum's inputs put particles inside no obstacle, a half-plane, a circle and both, in two
// environments whose k_r / k_d differ; each is asked twice, its contact the half-plane's and then
// the circle's, so that repulsionForce answers for each obstacle.
#include <functional>

#include "mistakes/library/measured/tasks.h"

namespace a6::grader::measured {
namespace {

#include "reference/physics.inc"

using harness::ForcesRequest;

ForcesRequest baseRequest() {
  ForcesRequest r;
  r.particle.x = Vec2(0.3, 2.0), r.particle.v = Vec2(1.2, -0.5);
  r.particle.m = 0.8, r.particle.temperature = 350;
  r.env.gravity = Vec2(0, -9.81), r.env.airTemperature = 293.15;
  r.env.buoyancy = 0.02, r.env.drag = 0.3, r.env.repulsion = 500;
  r.contact.depth = 0.1, r.contact.normal = Vec2(0.6, 0.8);
  return r;
}

// Around the base request, one variable changed at a time.
std::vector<ForcesRequest> partRequests() {
  using Change = std::function<void(ForcesRequest&)>;
  const std::vector<Change> changes = {
      [](ForcesRequest&) {},
      [](ForcesRequest& r) { r.particle.m = 2; },
      [](ForcesRequest& r) { r.env.gravity = Vec2(1.5, -4); },
      [](ForcesRequest& r) { r.particle.temperature = 400; },
      [](ForcesRequest& r) { r.particle.temperature = 250; },
      [](ForcesRequest& r) { r.particle.temperature = 293.15; },
      [](ForcesRequest& r) { r.env.airTemperature = 270; },
      [](ForcesRequest& r) { r.env.buoyancy = 0.05; },
      [](ForcesRequest& r) { r.particle.v = Vec2(-2.5, 0.7); },
      [](ForcesRequest& r) { r.particle.v = Vec2(2.4, -1.0); },
      [](ForcesRequest& r) { r.particle.v = Vec2::Zero(); },
      [](ForcesRequest& r) { r.env.drag = 0.9; },
      [](ForcesRequest& r) { r.env.repulsion = 1200; },
      [](ForcesRequest& r) { r.contact.depth = 0.25; },
      [](ForcesRequest& r) { r.contact.normal = Vec2(-1, 0); },
      [](ForcesRequest& r) { r.contact.depth = -0.2; },
      [](ForcesRequest& r) { r.contact.depth = 0; },
  };
  std::vector<ForcesRequest> out;
  for (const Change& change : changes) {
    ForcesRequest r = baseRequest();
    change(r);
    out.push_back(r);
  }
  return out;
}

// The sum's environments: a floor (y < 0) and a disc, with k_r / k_d of two sizes.
Environment sumEnvironment(int k) {
  Environment env = baseRequest().env;
  env.planes = {HalfPlane{Vec2(0, 1), 0}};
  env.circles = {CircleObstacle{Vec2(2, 0.5), 0.8}};
  if (k == 1) env.repulsion = 800, env.drag = 0.9, env.gravity = Vec2(0.8, -9), env.buoyancy = 0.03;
  return env;
}

// The sum's particles: inside nothing, the floor, the disc, both; each with its own m, v, T.
std::vector<Particle> sumParticles() {
  const Vec2 xs[] = {Vec2(0.3, 2.0), Vec2(-1, -0.15), Vec2(2.2, 1.0), Vec2(2.1, -0.1)};
  const Vec2 vs[] = {Vec2(1.2, -0.5), Vec2(-0.7, 0.9), Vec2(0.4, 1.5), Vec2(-1.1, -0.3)};
  const double ms[] = {0.8, 1.7, 0.5, 1.2}, ts[] = {350, 260, 410, 300};
  std::vector<Particle> out;
  for (int i = 0; i < 4; ++i) {
    Particle p;
    p.x = xs[i], p.v = vs[i], p.m = ms[i], p.temperature = ts[i];
    out.push_back(p);
  }
  return out;
}

std::string whereOf(const ForcesRequest& r) {
  return "m = " + number(r.particle.m) + ", v = " + vector(r.particle.v) +
         ", T = " + number(r.particle.temperature) + ", g = " + vector(r.env.gravity) +
         ", T_air = " + number(r.env.airTemperature) + ", b = " + number(r.env.buoyancy) +
         ", k_d = " + number(r.env.drag);
}

// A part of task 2 from the parts' answers: `value` gives its physics' value, the student's, the
// variables' values and the terms' of one answer.
Part forcePart(const Transcript& t, Part part,
               const std::function<void(const ExchangeOf<ForcesRequest>&, Sample&)>& fill) {
  for (const auto& x : answersTo<ForcesRequest>(t, "t2.parts")) {
    Sample s;
    s.where = whereOf(x.request);
    fill(x, s);
    part.samples.push_back(std::move(s));
  }
  return part;
}

Part gravityPart(const Transcript& t) {
  return forcePart(t,
                   {"gravity",
                    "gravity",
                    kGravityFormula,
                    "N",
                    false,
                    {{"m", false, 1}, {"|g|", false, 1}},
                    {{"m g"}},
                    {}},
                   [](const ExchangeOf<ForcesRequest>& x, Sample& s) {
                     const Particle& p = x.request.particle;
                     s.values = {p.m, x.request.env.gravity.norm()};
                     s.physics = referenceGravity(p, x.request.env);
                     s.yours = x.result.gravity;
                     s.terms = {p.m * x.request.env.gravity};
                   });
}

Part buoyancyPart(const Transcript& t) {
  return forcePart(t,
                   {"buoyancy",
                    "buoyancy",
                    kBuoyancyFormula,
                    "N",
                    false,
                    {{"b", true, 1}, {"T"}, {"T_air"}},
                    {{"b T (0, 1)"}, {"-b T_air (0, 1)"}},
                    {}},
                   [](const ExchangeOf<ForcesRequest>& x, Sample& s) {
                     const Particle& p = x.request.particle;
                     const Environment& env = x.request.env;
                     s.values = {env.buoyancy, p.temperature, env.airTemperature};
                     s.physics = referenceBuoyancy(p, env);
                     s.yours = x.result.buoyancy;
                     s.terms = {env.buoyancy * p.temperature * Vec2(0, 1),
                                -env.buoyancy * env.airTemperature * Vec2(0, 1)};
                   });
}

Part dragPart(const Transcript& t) {
  return forcePart(t,
                   {"drag",
                    "drag",
                    kDragFormula,
                    "N",
                    false,
                    {{"k_d", true, 1}, {"|v|", false, 1}, {"m"}},
                    {{"-k_d v"}},
                    {}},
                   [](const ExchangeOf<ForcesRequest>& x, Sample& s) {
                     const Particle& p = x.request.particle;
                     s.values = {x.request.env.drag, std::max(p.v.norm(), 1e-3), p.m};
                     s.physics = referenceDrag(p, x.request.env);
                     s.yours = x.result.drag;
                     s.terms = {-x.request.env.drag * p.v};
                   });
}

Part repulsionPart(const Transcript& t) {
  Part part{"repulsion",
            "repulsion",
            "k_r d n while d > 0",
            "N",
            false,
            {{"k_r", true, 1}, {"d", false, 1}},
            {{"k_r d n while inside (d > 0)"}, {"k_r d n outside the obstacle (d ≤ 0)", 0}},
            {}};
  return forcePart(t, part, [](const ExchangeOf<ForcesRequest>& x, Sample& s) {
    const Contact& c = x.request.contact;
    const double kr = x.request.env.repulsion;
    const Vec2 push = kr * c.depth * c.normal;
    s.values = {kr, std::max(std::abs(c.depth), 1e-3)};
    s.physics = referenceRepulsion(kr, c);
    s.yours = x.result.repulsion;
    s.terms = {c.depth > 0 ? push : Vec2::Zero(), c.depth > 0 ? Vec2::Zero() : push};
    s.where = "k_r = " + number(kr) + ", d = " + number(c.depth) + ", n = " + vector(c.normal);
  });
}

// The sum's terms at one particle: the student's own gravity, buoyancy and drag, each
// obstacle's repulsion as the student's repulsionForce gave it, and that repulsion with k_d.
std::vector<Vec2> sumTerms(const ExchangeOf<ForcesRequest>& plane,
                           const ExchangeOf<ForcesRequest>& circle) {
  const Environment& env = plane.request.env;
  const Vec2 x = plane.request.particle.x;
  return {plane.result.gravity,
          plane.result.buoyancy,
          plane.result.drag,
          plane.result.repulsion,
          circle.result.repulsion,
          referenceRepulsion(env.drag, contactWith(env.planes[0], x)),
          referenceRepulsion(env.drag, contactWith(env.circles[0], x))};
}

Part sumPart(const Transcript& t) {
  Part part{"external",
            "externalForce",
            "gravity + buoyancy + drag + every obstacle's repulsion",
            "N",
            false,
            {},
            {},
            {}};
  part.terms = {{"gravity"},
                {"buoyancy"},
                {"drag"},
                {"the half-planes' repulsion"},
                {"the circles' repulsion"},
                {"k_d d n for the half-planes", 0, 3},
                {"k_d d n for the circles", 0, 4}};
  const auto planes = answersTo<ForcesRequest>(t, "t2.sum.plane");
  const auto circles = answersTo<ForcesRequest>(t, "t2.sum.circle");
  for (const auto& p : planes) {
    for (const auto& c : circles) {
      if (c.request.particle.x != p.request.particle.x ||
          c.request.env.repulsion != p.request.env.repulsion)
        continue;
      Sample s{{}, Vec2::Zero(), p.result.total, sumTerms(p, c), {}};
      for (std::size_t j = 0; j < 5; ++j) s.physics += s.terms[j];
      s.where = "x = " + vector(p.request.particle.x) + " (" +
                (p.request.contact.depth > 0 ? "inside the floor" : "above the floor") +
                (c.request.contact.depth > 0 ? ", inside the disc)" : ", outside the disc)") +
                ", your parts summed";
      part.samples.push_back(std::move(s));
    }
  }
  return part;
}

}  // namespace

void designForces(std::vector<Designed>& out) {
  for (const ForcesRequest& r : partRequests()) out.push_back(designed("t2.parts", r));
  for (int k = 0; k < 2; ++k) {
    for (const Particle& p : sumParticles()) {
      ForcesRequest r;
      r.particle = p;
      r.env = sumEnvironment(k);
      r.contact = contactWith(r.env.planes[0], p.x);
      out.push_back(designed("t2.sum.plane", r));
      r.contact = contactWith(r.env.circles[0], p.x);
      out.push_back(designed("t2.sum.circle", r));
    }
  }
}

std::vector<Finding> measureForces(const Transcript& t) {
  return {measure(gravityPart(t)), measure(buoyancyPart(t)), measure(dragPart(t)),
          measure(repulsionPart(t)), measure(sumPart(t))};
}

}  // namespace a6::grader::measured
