// The student's code as the checks see it in the grader: two probes built from the same objects,
// each request routed to one of them by what it asks for. Takes the two ProbeClients; gives their
// answers, and their incidents and output added up.
#pragma once

#include <chrono>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "harness/student_code.h"
#include "probe/probe_client.h"

namespace a6::grader {

/// The student's code as two probes built from the same objects (grader/DESIGN.md, "Two
/// probes"): `plain` answers every request except those that ask for the reference forces (the
/// steppers of tasks 3 and 5), which `models` answers, asking the grader for each force
/// (ProbeClient::serveForces). Neither holds a reference model; the probe that answers tasks 1
/// and 2 cannot even ask for one.
class ProbePair final : public harness::StudentCode {
 public:
  ProbePair(std::unique_ptr<ProbeClient> plain, std::unique_ptr<ProbeClient> models);

  /// For both probes (see ProbeClient).
  void startCheck(double limit, std::chrono::steady_clock::time_point hardEnd);
  /// Each probe may be started `more` more times from now on (a new check's restarts).
  void allowMoreStarts(int more);

  /// How many forces the grader has answered the probe with the reference forces so far.
  std::size_t forceAnswers() const;
  /// What both printed (the plain probe's first), capped at `cap` bytes.
  std::string output(std::size_t cap) const;
  /// How often a probe was started again after a crash or a time limit (0 when each was
  /// started at most once).
  int restarts() const;
  /// Both probes' incidents, added up.
  ProbeIncidents incidents() const;
  std::vector<std::string> notes() const;

 private:
  harness::Answer respond(const harness::Request& request) override;

  std::unique_ptr<ProbeClient> plain_, models_;
};

}  // namespace a6::grader
