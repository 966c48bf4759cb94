// The out-of-process StudentCode: each request goes to the sandboxed probe over a pipe and comes
// back as plain data. One probe serves every request (a process per request would cost more than
// most requests). A crash, a time-out, garbage or output between requests fails that request
// with the reason and leaves the probe's state unknown, so it is killed and the next request
// starts a fresh one in a fresh work folder. After `maxStarts` starts every request fails at
// once: code that crashes on every request must not take forever to grade.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "harness/student_code.h"
#include "sandbox/sandbox.h"

namespace a6::grader {

/// The wall-clock time a request, and a check, gets on top of its time limit for each force the
/// grader answered during it (ProbeClient::serveForces): that round trip is the grader's doing,
/// not the student's code's. About 20 us on an idle machine, milliseconds on a loaded one; the
/// allowance is 2 ms a force, at most 4 times the limit (so code that asks for forces in an
/// endless loop still stops).
constexpr double kForceWaitSeconds = 0.002;
constexpr double kForceWaitCap = 4;
inline double forceWaitAllowance(std::size_t answers, double limit) {
  const double extra = static_cast<double>(answers) * kForceWaitSeconds;
  return extra < kForceWaitCap * limit ? extra : kForceWaitCap * limit;
}

/// The words of a failed request, as students read them. With A6_REWORD_MESSAGES=1 in the
/// grader's environment every such message is prefixed "[reworded] ": the test that proves no
/// decision (a score, a retry, a start-up verdict) reads the words, only Outcome::fault, grades
/// with and without it and compares.
std::string reworded(std::string words);

/// What a probe sees (an allow-list, sandbox/sandbox.h): the system's libraries, /proc, the
/// devices null, zero and urandom, and its own program and work folder; nothing else of the
/// machine: not the grader's trees (`secrets`, named first where nothing can be hidden), not the
/// rest of the work folder (the rendered images), not /tmp or any folder others may write to.
inline SandboxView probeView(const std::vector<std::filesystem::path>& secrets) {
  return allowOnly({}, secrets);
}

/// What the student's code did to the probes, for a TA's "to look at" list (a6_batch): each
/// counts once per probe stopped for it.
struct ProbeIncidents {
  int crashes = 0;        ///< killed by a signal (SIGSEGV, SIGABRT, SIGXCPU...) or exited
  int timeouts = 0;       ///< stopped at a request's time limit
  int startFailures = 0;  ///< could not be started, or failed the start-up check
};

class ProbeClient final : public harness::StudentCode {
 public:
  /// `probe`: the linked probe executable; `workRoot`: where fresh working directories go
  /// (workRoot/probe-1, probe-2, ...; each removed when its probe stops). Never throws.
  ProbeClient(std::filesystem::path probe, std::filesystem::path workRoot, Limits limits);
  ~ProbeClient() override;

  /// Each next request may take `seconds` of wall-clock time from its start (plus the force
  /// allowance); ends a check window.
  void setRequestTimeout(double seconds);
  /// A check starts now: its requests together may take `limit` seconds of wall-clock time plus
  /// the allowance for the forces answered since now (counted once, here), and none runs past
  /// `hardEnd`.
  void startCheck(double limit, std::chrono::steady_clock::time_point hardEnd);
  /// Paths the probe must not see (the solution, hidden tests, goldens: Kit::secrets), and
  /// paths inside them it must (SandboxSpec::hide, reveal). For the next probe started.
  void setHidden(std::vector<std::filesystem::path> hide,
                 std::vector<std::filesystem::path> reveal = {});
  /// Force models the grader answers the probe's force requests with (harness/force_channel.h:
  /// the reference forces of the checks of tasks 3 and 5, which never enter the probe). For the
  /// next probe started; empty models (the default): the probe uses the student's own forces.
  void serveForces(ForceModel models);
  /// How many forces the grader has answered this client's probes so far.
  std::size_t forceAnswers() const;
  /// How many probes may be started in all (default 50).
  void setMaxStarts(int starts);
  /// Who the probe runs as when the grader is root (default nobody). Graders running side by
  /// side should use a uid each: RLIMIT_NPROC and file access are per user.
  void setUser(uid_t uid, gid_t gid);

  /// Everything the probes printed so far, capped at Limits::outputBytes over all of them, plus
  /// a marker line where one ended ("[a6: probe 2 crashed: killed by SIGSEGV ...]"), for the
  /// report; never parsed.
  std::string output() const;
  /// How many probes were started (1 + restarts after crashes and timeouts).
  int starts() const;
  ProbeIncidents incidents() const;
  /// What the sandbox could not apply (not root, namespaces refused), once each.
  std::vector<std::string> notes() const;
  /// Stops the running probe, if any (the next request starts a fresh one).
  void stop();

 private:
  harness::Answer respond(const harness::Request& request) override;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace a6::grader
