// Two probes, one StudentCode (see probe_pair.h).
#include "probe/probe_pair.h"

#include <algorithm>
#include <type_traits>
#include <utility>
#include <variant>

namespace a6::grader {

ProbePair::ProbePair(std::unique_ptr<ProbeClient> plain, std::unique_ptr<ProbeClient> models)
    : plain_(std::move(plain)), models_(std::move(models)) {}

void ProbePair::startCheck(double limit, std::chrono::steady_clock::time_point hardEnd) {
  plain_->startCheck(limit, hardEnd);
  models_->startCheck(limit, hardEnd);
}

void ProbePair::allowMoreStarts(int more) {
  plain_->setMaxStarts(plain_->starts() + more);
  models_->setMaxStarts(models_->starts() + more);
}

namespace {
// Whether a request asks for the reference forces (a field referenceForces, set).
template <class R, class = void>
struct HasReferenceForces : std::false_type {};
template <class R>
struct HasReferenceForces<R, std::void_t<decltype(R::referenceForces)>> : std::true_type {};

bool asksForReferenceForces(const harness::Request& request) {
  return std::visit(
      [](const auto& r) {
        if constexpr (HasReferenceForces<std::decay_t<decltype(r)>>::value) {
          return r.referenceForces;
        } else {
          return false;
        }
      },
      request);
}
}  // namespace

harness::Answer ProbePair::respond(const harness::Request& request) {
  return asksForReferenceForces(request) ? models_->ask(request) : plain_->ask(request);
}

std::string ProbePair::output(std::size_t cap) const {
  std::string text = plain_->output();
  const std::string models = models_->output();
  if (!models.empty()) text += "[a6: what the probe with the reference forces printed]\n" + models;
  if (text.size() > cap) text.resize(cap);
  return text;
}

std::size_t ProbePair::forceAnswers() const { return models_->forceAnswers(); }

int ProbePair::restarts() const {
  return std::max(0, plain_->starts() - 1) + std::max(0, models_->starts() - 1);
}

ProbeIncidents ProbePair::incidents() const {
  const ProbeIncidents a = plain_->incidents(), b = models_->incidents();
  return {a.crashes + b.crashes, a.timeouts + b.timeouts, a.startFailures + b.startFailures};
}

std::vector<std::string> ProbePair::notes() const {
  std::vector<std::string> all = plain_->notes();
  for (const std::string& n : models_->notes()) {
    if (std::find(all.begin(), all.end(), n) == all.end()) all.push_back(n);
  }
  return all;
}

}  // namespace a6::grader
