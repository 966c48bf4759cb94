#include "checks/recording_student.h"

#include <gtest/gtest.h>

namespace a6::grader {
namespace {

// Keeps a copy of the exchange when a public check asked and the student's code ran to the end.
template <class Request, class Result>
Result keep(std::vector<Exchange<Request, Result>>& into, const Request& request, Result result) {
  std::string check = publicCheckRunning();
  if (!check.empty() && result.ok()) into.push_back({std::move(check), request, result});
  return result;
}

}  // namespace

std::string publicCheckRunning() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  if (info == nullptr) return "";
  const std::string suite = info->test_suite_name();
  if (suite.rfind("Task", 0) != 0 || suite.find("Hidden") != std::string::npos) return "";
  if (suite.size() < 5 || suite[4] < '1' || suite[4] > '7') return "";
  return suite + "." + info->name();
}

harness::SpringForceResult RecordingStudent::springForce(const harness::SpringForceRequest& r) {
  return keep(transcript_.springs, r, inner_.springForce(r));
}
harness::ForcesResult RecordingStudent::forces(const harness::ForcesRequest& r) {
  return keep(transcript_.forces, r, inner_.forces(r));
}
harness::SimulateResult RecordingStudent::simulate(const harness::SimulateRequest& r) {
  return keep(transcript_.simulations, r, inner_.simulate(r));
}
harness::ClothResult RecordingStudent::buildCloth(const ClothSpec& s) {
  return keep(transcript_.cloths, s, inner_.buildCloth(s));
}
harness::ParticlesResult RecordingStudent::emit(const harness::EmitRequest& r) {
  return keep(transcript_.emissions, r, inner_.emit(r));
}
harness::ParticlesResult RecordingStudent::runParticles(const harness::ParticleRunRequest& r) {
  return keep(transcript_.particleRuns, r, inner_.runParticles(r));
}
harness::Box2DResult RecordingStudent::runBox2D(const harness::Box2DRequest& r) {
  return keep(transcript_.box2d, r, inner_.runBox2D(r));
}

}  // namespace a6::grader
