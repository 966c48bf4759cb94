// The solution agrees with the reference physics on every check's inputs. The physics suite
// (public and hidden checks) runs with the solution linked in, as the in-process suite does;
// every request the reference can answer (grader/reference/: the spring force and its
// Jacobians, the forces, the steps of tasks 3 and 7 with the reference forces, the cloth, the
// update of particles already alive) is answered by the reference too, and the answers compared.
// Exit code 0 when every kind was compared at least once and no answer differed; 1 otherwise, with
// the first differences. The checks' own verdicts are the physics test's, not this one's.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "reference/cloth.h"
#include "reference/steppers.h"
#include "suite.h"

namespace {
#include A6_FORCE_MODELS  // the reference physics (grader/reference/physics.inc)

using namespace a6;
using namespace a6::harness;

constexpr double kForces = 1e-9;  ///< relative: the same formula, another order of operations
constexpr double kRuns = 1e-6;    ///< relative: many steps, and task 7's solver against a dense one

bool near(const Vec2& a, const Vec2& b, double scale, double tol) {
  return (a - b).norm() <= tol * (1 + scale);
}

bool near(const Mat2& a, const Mat2& b, double scale) {
  return (a - b).norm() <= kForces * (1 + scale);
}

bool sameParticles(const std::vector<Particle>& a, const std::vector<Particle>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double scale = a[i].x.norm() + a[i].v.norm();
    if (!near(a[i].x, b[i].x, scale, kRuns) || !near(a[i].v, b[i].v, scale, kRuns)) return false;
    if (std::abs(a[i].temperature - b[i].temperature) > kRuns * (1 + b[i].temperature))
      return false;
  }
  return true;
}

// What one kind of request gave: how many answers were compared, and the first that differed.
struct Tally {
  int compared = 0;
  std::vector<std::string> differences;
  void add(bool same, const std::string& what) {
    ++compared;
    if (!same && differences.size() < 5) differences.push_back(what);
    if (!same) ++differing;
  }
  int differing = 0;
};

std::map<std::string, Tally> gTallies;

std::string where() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return info ? std::string(info->test_suite_name()) + "." + info->name() : "(no check)";
}

void compare(const SpringForceRequest& r, const SpringForceResult& got) {
  const SpringTerms t = referenceSpringTerms(r.p1, r.p2, r.restLength, r.ks, r.kd);
  const double scale = t.elastic.norm() + t.damping.norm();
  gTallies["springForce"].add(near(got.force, t.elastic + t.damping, scale, kForces), where());
}

void compare(const JacobiansRequest& r, const JacobiansResult& got) {
  const SpringForceRequest& s = r.spring;
  const SpringJacobians j = referenceSpringJacobians(s.p1.x, s.p2.x, s.restLength, s.ks, s.kd);
  const double scale = j.dfdx.norm() + j.dfdv.norm();
  gTallies["springJacobians"].add(near(got.dfdx, j.dfdx, scale) && near(got.dfdv, j.dfdv, scale),
                                  where());
}

void compare(const ForcesRequest& r, const ForcesResult& got) {
  const Particle& p = r.particle;
  const Vec2 total = referenceExternalForce(p, r.env);
  const double scale = total.norm() + referenceGravity(p, r.env).norm() +
                       referenceDrag(p, r.env).norm() + referenceBuoyancy(p, r.env).norm() +
                       referenceRepulsion(r.env.repulsion, r.contact).norm();
  const bool same =
      near(got.gravity, referenceGravity(p, r.env), scale, kForces) &&
      near(got.buoyancy, referenceBuoyancy(p, r.env), scale, kForces) &&
      near(got.drag, referenceDrag(p, r.env), scale, kForces) &&
      near(got.repulsion, referenceRepulsion(r.env.repulsion, r.contact), scale, kForces) &&
      near(got.total, total, scale, kForces);
  gTallies["forces"].add(same, where());
}

void compare(const SimulateRequest& r, const SimulateResult& got) {
  const auto want =
      r.implicit ? grader::reference::simulateImplicit(r, {}) : grader::reference::simulate(r, {});
  if (!want) return;  // the student's own forces, or too large for the dense solve
  bool same = want->recordedFrames == got.recordedFrames;
  for (std::size_t k = 0; same && k < want->states.size(); ++k)
    same = sameParticles(got.states[k], want->states[k]);
  gTallies[r.implicit ? "stepImplicit" : "step"].add(same, where());
}

void compare(const ParticleRunRequest& r, const ParticlesResult& got) {
  const auto want = grader::reference::runParticles(r, grader::reference::ParticleFlaw::None);
  if (!want) return;  // an emitter, or the student's own forces
  gTallies["particleUpdate"].add(
      want->counts == got.counts && sameParticles(got.particles, want->particles), where());
}

void compare(const ClothRequest& r, const ClothResult& got) {
  if (r.spec.n < 1 || r.spec.n > 200) return;  // no cloth: the checks of bad specs
  gTallies["cloth"].add(
      grader::reference::sameCloth(got, grader::reference::referenceCloth(r.spec), kForces),
      where());
}

template <class R>
void compare(const R&, const typename R::Result&) {}  // emission, joints, scenes

// The solution, with each answer compared with the reference's.
class Compared final : public StudentCode {
 public:
  explicit Compared(StudentCode& inner) : inner_(inner) {}

 private:
  Answer respond(const Request& request) override {
    Answer answer = inner_.ask(request);
    if (outcomeOf(answer).ok()) {
      std::visit(
          [&](const auto& r) {
            using R = std::decay_t<decltype(r)>;
            compare(r, std::get<kKindOf<R>>(answer));
          },
          request);
    }
    return answer;
  }
  StudentCode& inner_;
};

std::unique_ptr<StudentCode> gSolution, gCompared;

}  // namespace

namespace a6::test {
harness::StudentCode& student() { return *gCompared; }
}  // namespace a6::test

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
  delete listeners.Release(listeners.default_result_printer());
  gSolution = makeInProcess(referenceForceModel());
  gCompared = std::make_unique<Compared>(*gSolution);
  if (RUN_ALL_TESTS() != 0) std::printf("(checks failed: the physics test says which)\n");
  int status = 0;
  for (const char* kind : {"springForce", "springJacobians", "forces", "step", "stepImplicit",
                           "cloth", "particleUpdate"}) {
    const Tally& t = gTallies[kind];
    std::printf("%-16s %5d answers compared, %d differ\n", kind, t.compared, t.differing);
    for (const std::string& check : t.differences) std::printf("  differs in %s\n", check.c_str());
    if (t.compared == 0 || t.differing != 0) status = 1;
  }
  std::printf(status == 0 ? "The solution agrees with the reference physics.\n"
                          : "The solution and the reference physics disagree (above).\n");
  return status;
}
