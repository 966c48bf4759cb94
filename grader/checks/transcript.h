// What the student's code answered to the public checks of tasks 1 to 7 (not the hidden ones,
// whose inputs are random, nor the images): each request beside its result, in the order the
// checks asked. The checks stage gives it (RecordingStudent); the mistakes stage compares it
// with the known mistakes (grader/mistakes/). Only requests that ran to the end are kept.
#pragma once

#include <string>
#include <vector>

#include "harness/student_code.h"

namespace a6::grader {

/// One request and the student's answer to it.
template <class Request, class Result>
struct Exchange {
  std::string check;  ///< the check that asked, "Task1Spring.StretchedAlongX"
  Request request;
  Result result;
};

struct Transcript {
  std::vector<Exchange<harness::SpringForceRequest, harness::SpringForceResult>> springs;
  std::vector<Exchange<harness::ForcesRequest, harness::ForcesResult>> forces;
  std::vector<Exchange<harness::SimulateRequest, harness::SimulateResult>> simulations;
  std::vector<Exchange<ClothSpec, harness::ClothResult>> cloths;
  std::vector<Exchange<harness::EmitRequest, harness::ParticlesResult>> emissions;
  std::vector<Exchange<harness::ParticleRunRequest, harness::ParticlesResult>> particleRuns;
  std::vector<Exchange<harness::Box2DRequest, harness::Box2DResult>> box2d;
};

}  // namespace a6::grader
