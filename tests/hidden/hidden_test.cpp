// Hidden checks (graders only: never in a student release). The contracts of the public checks
// of tasks 1 to 4, on inputs drawn at random from the seed the grader chooses for each submission
// and records in its report (a6_grade --seed N regrades with the same inputs), so a submission
// cannot recognise its inputs and special-case them.
//
// The seed is GoogleTest's --gtest_random_seed (a6_grade sets it); without one (ctest) it is
// fixed, so the instructors' runs are reproducible too. Each check mixes in its own name, so
// adding a check changes no other check's inputs. Every expected value comes from the reference
// physics (grader/reference/physics.inc) or from the slide's formula written out here, and is
// compared with a relative tolerance: a correct solution that adds the same terms in another order
// passes.
//
// Suites are named Task<N>Hidden: they count for task N in the per-task summary, and the rubric
// gives them their own items (grader/rubric.toml: shown to students after the due date).
#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "cloth_result.h"
#include "gtest_flags.h"
#include "reference/cloth.h"
#include "reference/steppers.h"
#include "scales.h"
#include "suite.h"

namespace a6::test {
namespace {

#include A6_FORCE_MODELS  // the reference physics (grader/reference/physics.inc)

constexpr std::uint64_t kSeedWithoutGrader = 20261122;

// The random numbers of the running check: the run's seed mixed with the check's name.
class Draw {
 public:
  Draw() {
    const std::int32_t flag = A6_GTEST_FLAG_GET(random_seed);
    seed_ = flag != 0 ? static_cast<std::uint64_t>(flag) : kSeedWithoutGrader;
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = std::string(info->test_suite_name()) + "." + info->name();
    engine_.seed(seed_ ^ std::hash<std::string>{}(name));
  }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(engine_);
  }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  bool coin() { return integer(0, 1) == 1; }
  Vec2 vec(double r) { return Vec2(uniform(-r, r), uniform(-r, r)); }
  Vec2 unit() {
    const double a = uniform(0, 2 * M_PI);
    return Vec2(std::cos(a), std::sin(a));
  }
  /// Appended to every failure: how to draw the same inputs again (a6_grade derives GoogleTest's
  /// seed from its own --seed, which the report records; a6_tests takes it directly).
  std::string seed() const {
    return " [random inputs: --gtest_random_seed=" + std::to_string(seed_) +
           "; a6_grade --seed with the report's seed draws the same]";
  }

 private:
  std::uint64_t seed_ = 0;
  std::mt19937_64 engine_;
};

// The reference spring force on p2 of a spring (l0, ks, kd) from p1 to p2.
Vec2 referenceForce(Particle& p1, Particle& p2, double restLength, double ks, double kd) {
  Spring s;
  s.p1 = &p1;
  s.p2 = &p2;
  s.restLength = restLength;
  s.ks = ks;
  s.kd = kd;
  return referenceSpringForce(s);
}

// Task 1 -------------------------------------------------------------------------------------

TEST(Task1Hidden, RandomSpringsMatchTheSlideFormula) {
  Draw draw;
  for (int k = 0; k < 200; ++k) {
    harness::SpringForceRequest r;
    r.p1.x = draw.vec(5);
    do {
      r.p2.x = draw.vec(5);
    } while ((r.p2.x - r.p1.x).norm() < 0.05);
    r.p1.v = draw.vec(3);
    r.p2.v = draw.vec(3);
    r.restLength = draw.uniform(0.1, 3);
    r.ks = draw.uniform(1, 500);
    r.kd = draw.coin() ? draw.uniform(0, 5) : 0;
    Particle p1 = r.p1, p2 = r.p2;
    const Vec2 expected = referenceForce(p1, p2, r.restLength, r.ks, r.kd);
    const harness::SpringForceResult result = student().ask(r);
    A6_ASSERT_RAN(result);
    ASSERT_VEC_NEAR(
        result.force, expected,
        relativeTo(springForceScale(r.p1.x, r.p2.x, r.p1.v, r.p2.v, r.restLength, r.ks, r.kd)))
        << "input: p1 " << str(r.p1) << ", p2 " << str(r.p2) << ", l0=" << r.restLength
        << ", ks=" << r.ks << ", kd=" << r.kd << draw.seed()
        << hint(std::string("f2 = ") + kSpringForceFormula +
                ", with e = (x2 - x1) / l and v_rel = (v2 - v1)·e");
  }
}

// Task 2 -------------------------------------------------------------------------------------

TEST(Task2Hidden, RandomParticlesAndEnvironmentsMatchTheSlideFormulas) {
  Draw draw;
  for (int k = 0; k < 200; ++k) {
    harness::ForcesRequest r;
    Particle& p = r.particle;
    p.x = draw.vec(2);
    p.v = draw.vec(4);
    p.m = draw.uniform(0.01, 5);
    p.temperature = draw.uniform(250, 900);
    Environment& env = r.env;
    env.gravity = draw.unit() * draw.uniform(0, 15);
    env.airTemperature = draw.uniform(250, 320);
    env.buoyancy = draw.uniform(0, 0.05);
    env.drag = draw.uniform(0, 2);
    env.repulsion = draw.uniform(0, 2000);
    for (int planes = draw.integer(0, 3); planes > 0; --planes) {
      HalfPlane plane;
      plane.normal = draw.unit();
      plane.offset = draw.uniform(-2, 2);
      env.planes.push_back(plane);
    }
    for (int circles = draw.integer(0, 3); circles > 0; --circles) {
      CircleObstacle circle;
      circle.center = draw.vec(2);
      circle.radius = draw.uniform(0.1, 1.5);
      env.circles.push_back(circle);
    }
    r.contact.depth = draw.uniform(-0.2, 0.2);
    r.contact.normal = draw.unit();

    const harness::ForcesResult result = student().ask(r);
    A6_ASSERT_RAN(result);
    const Tolerance tol = relativeTo(externalForceScale(p, env, r.contact.depth));
    const std::string in = "input: particle " + str(p) + ", g=" + str(env.gravity) +
                           ", T_air=" + num(env.airTemperature) + ", b=" + num(env.buoyancy) +
                           ", k_d=" + num(env.drag) + ", k_r=" + num(env.repulsion) + ", " +
                           std::to_string(env.planes.size()) + " plane(s), " +
                           std::to_string(env.circles.size()) + " circle(s)" + draw.seed();
    const std::string is = " is ";
    ASSERT_VEC_NEAR(result.gravity, referenceGravity(p, env), tol)
        << in << hint("gravity" + is + kGravityFormula);
    ASSERT_VEC_NEAR(result.buoyancy, referenceBuoyancy(p, env), tol)
        << in << hint("buoyancy" + is + kBuoyancyFormula);
    ASSERT_VEC_NEAR(result.drag, referenceDrag(p, env), tol)
        << in << hint("drag" + is + kDragFormula);
    ASSERT_VEC_NEAR(result.repulsion, referenceRepulsion(env.repulsion, r.contact), tol)
        << in << ", contact depth " << num(r.contact.depth) << ", normal " << str(r.contact.normal)
        << hint("repulsion" + is + kRepulsionFormula + " while d > 0, and zero otherwise");
    const Vec2 total = referenceExternalForce(p, env);
    ASSERT_VEC_NEAR(result.total, total, tol)
        << in
        << hint(
               "externalForce is gravity + buoyancy + drag + the repulsion of every "
               "half-plane and every circle the particle is inside");
  }
}

// Task 3 -------------------------------------------------------------------------------------

// A random chain of 2 to 6 particles (the first one pinned or not), run 30 frames in 1 to 4
// substeps under random gravity and drag, its state recorded every 10 frames.
struct RandomChain {
  harness::SimulateRequest request;
  int n = 0;           ///< particles
  double spacing = 0;  ///< between neighbours, m
};

RandomChain randomChain(Draw& draw) {
  RandomChain chain;
  harness::SimulateRequest& r = chain.request;
  const int n = chain.n = draw.integer(2, 6);
  const double spacing = chain.spacing = draw.uniform(0.2, 0.6);
  const Vec2 dir = draw.unit();
  for (int i = 0; i < n; ++i) {
    Particle p;
    p.x = i * spacing * dir + draw.vec(0.05);
    p.v = draw.vec(0.5);
    p.m = draw.uniform(0.2, 1);
    p.pinned = i == 0 && draw.coin();
    r.particles.push_back(p);
  }
  for (int i = 0; i + 1 < n; ++i) {
    harness::SpringData s;
    s.i = i;
    s.j = i + 1;
    s.restLength = spacing;
    s.ks = draw.uniform(10, 150);
    s.kd = draw.uniform(0, 0.5);
    r.springs.push_back(s);
  }
  r.env.gravity = Vec2(0, -draw.uniform(0, 9.81));
  r.env.drag = draw.uniform(0, 0.3);
  r.env.buoyancy = 0;
  r.env.repulsion = 0;
  r.frameDt = 1.0 / 60;
  r.substeps = draw.integer(1, 4);
  r.stepOnly = false;
  r.frames = 30;
  r.recordEvery = 10;
  r.referenceForces = true;
  return chain;
}

// The student's recorded states against the reference steps, frame by frame.
void expectTheReferenceChain(const RandomChain& chain, const harness::SimulateResult& result,
                             const Draw& draw) {
  const harness::SimulateRequest& r = chain.request;
  const int n = chain.n;
  // Positions relative to the chain's extent, velocities to its speed after falling for the run.
  const double extent = n * chain.spacing + 0.1;
  const double speed = 0.5 + 9.81 * r.frames * r.frameDt;
  // The reference's symplectic Euler step with substeps (grader/reference/steppers.h).
  const std::optional<harness::SimulateResult> reference =
      grader::reference::simulate(r, grader::reference::StepForm{});
  ASSERT_TRUE(reference.has_value()) << "the reference stepper cannot run this chain";
  for (std::size_t recorded = 0; recorded < reference->states.size(); ++recorded) {
    const int frame = reference->recordedFrames[recorded];
    const std::vector<Particle>& expected = reference->states[recorded];
    const std::vector<Particle>& actual = result.states[recorded];
    ASSERT_EQ(actual.size(), expected.size()) << currentTask() << ": particles added or removed";
    for (std::size_t i = 0; i < expected.size(); ++i) {
      ASSERT_VEC_NEAR(actual[i].x, expected[i].x, relativeTo(extent, kManySteps))
          << "particle " << i << " of a chain of " << n << " after frame " << frame << " ("
          << r.substeps << " substep(s) of " << r.frameDt << " s / " << r.substeps
          << ", first particle " << (r.particles[0].pinned ? "pinned" : "free") << ")"
          << draw.seed()
          << hint(
                 "per substep: reset forces, add external and spring forces (p2 gets f, p1 "
                 "gets -f), then v += h f / m before x += h v, skipping pinned particles; "
                 "advance(dt, n) takes n steps of dt / n");
      ASSERT_VEC_NEAR(actual[i].v, expected[i].v, relativeTo(speed, kManySteps))
          << "velocity of particle " << i << " after frame " << frame << draw.seed()
          << hint("v += h f / m, with f the sum of this substep's forces");
    }
  }
}

TEST(Task3Hidden, RandomChainsFollowSymplecticEulerWithSubsteps) {
  Draw draw;
  for (int k = 0; k < 12; ++k) {
    const RandomChain chain = randomChain(draw);
    const harness::SimulateResult result = student().ask(chain.request);
    A6_ASSERT_RAN(result);
    ASSERT_EQ(result.states.size(), 3u) << currentTask() << ": expected 3 recorded states";
    expectTheReferenceChain(chain, result, draw);
    if (HasFatalFailure()) return;
  }
}

// Task 4 -------------------------------------------------------------------------------------

// A random cloth of 1 to 12 cells a side, with or without shear springs (the bending extension
// is extra credit: its checks are Task4Cloth.Bending*), its top corners pinned.
ClothSpec randomClothSpec(Draw& draw) {
  ClothSpec spec;
  spec.n = draw.integer(1, 12);
  spec.size = draw.uniform(0.3, 3);
  spec.origin = draw.vec(2);
  spec.particleMass = draw.uniform(0.001, 0.1);
  spec.ksStructural = draw.uniform(50, 500), spec.kdStructural = draw.uniform(0, 1);
  spec.shear = draw.coin();
  spec.ksShear = draw.uniform(10, 100), spec.kdShear = draw.uniform(0, 0.5);
  spec.bending = false;
  spec.pinTopCorners = true;
  return spec;
}

// The reference builder's cloth (grader/reference/cloth.h), read relative to base as the
// student's is.
harness::ClothResult referenceClothPart(const ClothSpec& spec) {
  return clothPart(grader::reference::referenceCloth(spec), spec.n);
}

// Every particle at its grid point, the top corners alone pinned, every mass particleMass.
// `in` describes the input.
void expectTheClothGrid(const ClothSpec& spec, const harness::ClothResult& result,
                        const std::string& in) {
  const int n = spec.n;
  const harness::ClothResult want = referenceClothPart(spec);
  const Tolerance length = relativeTo(spec.size + spec.origin.norm());
  ASSERT_EQ(result.particles.size(), want.particles.size())
      << currentTask() << ": " << in << hint("(n + 1)² particles");
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const auto k = static_cast<std::size_t>(clothIndex(i, j, n));
      const Particle &p = result.particles[k], &q = want.particles[k];
      ASSERT_VEC_NEAR(p.x, q.x, length)
          << "particle (" << i << ", " << j << "), " << in
          << hint("particle (i, j) sits at origin + (i, -j) size / n, index j (n + 1) + i");
      ASSERT_EQ(p.pinned, q.pinned) << currentTask() << ": particle (" << i << ", " << j << "), "
                                    << in << hint("pin the two top corners only");
      ASSERT_CLOSE(p.m, q.m, relativeTo(spec.particleMass))
          << in << hint("every particle has particleMass");
    }
  }
}

// The springs the cloth must have: unordered index pair -> (type, rest length, ks, kd).
using ClothSpringKey = std::pair<int, int>;
using ClothSprings = std::map<ClothSpringKey, std::tuple<SpringType, double, double, double>>;

ClothSprings expectedClothSprings(const ClothSpec& spec) {
  ClothSprings want;
  for (const harness::SpringData& s : referenceClothPart(spec).springs)
    want[{std::min(s.i, s.j), std::max(s.i, s.j)}] = {s.type, s.restLength, s.ks, s.kd};
  return want;
}

// Exactly the expected springs, each with its type, rest length and constants.
void expectTheClothSprings(const ClothSpec& spec, const harness::ClothResult& result,
                           const std::string& in) {
  const ClothSprings want = expectedClothSprings(spec);
  const Tolerance length = relativeTo(spec.size + spec.origin.norm());
  ASSERT_EQ(result.springs.size(), want.size())
      << currentTask() << ": the number of springs, " << in
      << hint(
             "structural springs to the right and below every particle, and both diagonals "
             "of every cell when shear is on; no spring twice");
  for (const harness::SpringData& s : result.springs) {
    const auto found = want.find({std::min(s.i, s.j), std::max(s.i, s.j)});
    ASSERT_TRUE(found != want.end())
        << currentTask() << ": a spring between particles " << s.i << " and " << s.j
        << " that the cloth does not have, " << in
        << hint(
               "structural: (i,j)-(i+1,j), (i,j)-(i,j+1); shear: (i,j)-(i+1,j+1), "
               "(i+1,j)-(i,j+1)");
    const auto& [type, l0, ks, kd] = found->second;
    ASSERT_EQ(s.type, type) << currentTask() << ": spring " << s.i << "-" << s.j << ", " << in
                            << hint("tag each spring with its SpringType");
    ASSERT_CLOSE(s.restLength, l0, length)
        << "spring " << s.i << "-" << s.j << ", " << in << hint("rest length h or sqrt(2) h");
    ASSERT_CLOSE(s.ks, ks, relativeTo(ks)) << "spring " << s.i << "-" << s.j << ", " << in
                                           << hint("the constants of the spring's type");
    ASSERT_CLOSE(s.kd, kd, relativeTo(kd)) << "spring " << s.i << "-" << s.j << ", " << in
                                           << hint("the constants of the spring's type");
  }
}

TEST(Task4Hidden, RandomClothSpecsGiveTheGridAndItsSprings) {
  Draw draw;
  for (int k = 0; k < 10; ++k) {
    const ClothSpec spec = randomClothSpec(draw);
    const int n = spec.n;
    const std::string in =
        "input: n=" + std::to_string(n) + ", size=" + num(spec.size) + ", origin " +
        str(spec.origin) + ", shear " + (spec.shear ? "on" : "off") +
        ", built into a system that already held " +
        std::to_string(harness::clothPrelude().particles.size()) + " particles" + draw.seed();

    // Read relative to base (a builder that forgot base loses Task4Cloth's check of it only).
    const harness::ClothResult result = clothPart(student().ask(harness::ClothRequest{spec}), n);
    A6_ASSERT_RAN(result);
    expectTheClothGrid(spec, result, in);
    if (HasFatalFailure()) return;
    expectTheClothSprings(spec, result, in);
    if (HasFatalFailure()) return;
  }
}

}  // namespace
}  // namespace a6::test
