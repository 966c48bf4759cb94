// The student's code with a witness: every request is passed on unchanged, and when the
// student's code did not answer (in the grader: it crashed, ran out of time or was not run), the
// running check is marked (suite.h: codeFailedInThisCheck), so that its hints, written for wrong
// answers, stay out of a failure that gave no answer. Takes the student's code to pass requests
// to; gives its answers unchanged.
#pragma once

#include "harness/student_code.h"
#include "suite.h"

namespace a6::test {

class WatchedStudent final : public harness::StudentCode {
 public:
  explicit WatchedStudent(harness::StudentCode& inner) : inner_(inner) {}

  harness::SpringForceResult springForce(const harness::SpringForceRequest& r) override {
    return watched(inner_.springForce(r));
  }
  harness::ForcesResult forces(const harness::ForcesRequest& r) override {
    return watched(inner_.forces(r));
  }
  harness::SimulateResult simulate(const harness::SimulateRequest& r) override {
    return watched(inner_.simulate(r));
  }
  harness::ClothResult buildCloth(const ClothSpec& s) override {
    return watched(inner_.buildCloth(s));
  }
  harness::ParticlesResult emit(const harness::EmitRequest& r) override {
    return watched(inner_.emit(r));
  }
  harness::ParticlesResult runParticles(const harness::ParticleRunRequest& r) override {
    return watched(inner_.runParticles(r));
  }
  harness::Box2DResult runBox2D(const harness::Box2DRequest& r) override {
    return watched(inner_.runBox2D(r));
  }
  harness::SceneResult runScene(const harness::SceneRequest& r) override {
    return watched(inner_.runScene(r));
  }

 private:
  template <class Result>
  static Result watched(Result result);

  harness::StudentCode& inner_;
};

template <class Result>
Result WatchedStudent::watched(Result result) {
  // An exception the student's code threw is its answer to this input, which a hint may
  // explain (an index outside the grid); a crash, a time-out or no run at all is not.
  if (!result.ok() && result.fault != harness::Fault::Exception) noteCodeFailed();
  return result;
}

}  // namespace a6::test
