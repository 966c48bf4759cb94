// Every time and memory limit of a grading, written once. The stages read these constants;
// `a6_grade --list-limits` prints them (kLimits below), and run_autograder, the docs test
// (scripts/docs-examples.sh) and whatever else needs a figure read it from there, not from a copy.
// To change a limit: change it here, then run `scripts/docs-examples.sh --update`.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

namespace a6::grader {

// --- The build ---------------------------------------------------------------------------------

/// The whole build of one submission may take this long (s): every compile gets what is left
/// of it, up to its own limit; a file not compiled when it is used up is graded with the
/// starter's stub.
constexpr double kDefaultBuildBudget = 150;
/// Each link gets at least this much, s, even when the build's budget is spent (a build links its
/// two probes, and again for a link the machine ended or a file that keeps the probe from
/// starting).
constexpr double kLinkAllowance = 10;
/// One compile's wall clock and CPU time, s, and its address space, bytes (a compile needs about
/// 200 MiB).
constexpr double kCompileSeconds = 60;
constexpr std::size_t kCompileMemoryBytes = std::size_t{512} << 20;
/// A probe that does not answer its first request within this long did not start, s.
constexpr double kStartupSeconds = 5;

// --- The checks --------------------------------------------------------------------------------

/// The time the student's code may take over all checks together (--time-budget), s: well
/// within Gradescope's default of 10 minutes for the whole run, which would otherwise end it
/// with a 0.
constexpr double kDefaultTimeBudget = 420;
/// The time limit of one check, s, where the rubric gives none (its `time_limit`).
constexpr double kDefaultTimeLimit = 10;
/// The probe's CPU time over its life, s, and its address space, bytes.
constexpr double kProbeCpuSeconds = 60;
constexpr std::size_t kProbeMemoryBytes = std::size_t{512} << 20;
/// The time one scene's replay may take, s (the probe's; beyond it the replay is left out).
constexpr double kReplaySeconds = 10;
/// The time all replays together may take, s: the scenes after it get none.
constexpr double kReplaysSeconds = 40;
/// The time the diagnosis's designed inputs may take together, s (the probe's; beyond it the
/// rest are not asked, and the diagnosis measures what was answered).
constexpr double kMeasureSeconds = 10;

// --- The grading as a whole ----------------------------------------------------------------------

/// The grader's own work in one grading, s: intake, the links past the budget, the start-up
/// checks (a few runs of kStartupSeconds, only for a program that does not start), its side of
/// the checks, naming the mistakes, the replays, the report. Seconds on an idle machine
/// (Gradescope's run_autograder allows 30); this much beside CI's load (other graders, builds and
/// CPU hogs on every core).
constexpr double kOwnWorkSeconds = 120;

/// The wall time of a grading, whatever the code does, s: the build's budget and a link's
/// allowance, the student's `timeBudget`, and the grader's own work as loaded as CI's. The
/// hostile ctests hold every grading to it.
constexpr double maxGradingSeconds(double timeBudget) {
  return kDefaultBuildBudget + kLinkAllowance + timeBudget + kOwnWorkSeconds;
}

/// On Gradescope (run_autograder): the student's code gets this much over all checks, and
/// a6_grade is stopped after the second figure, s: the build, a link's allowance, the checks and
/// 20 s of the grader's own work there (seconds on Gradescope's idle machine). Gradescope ends a
/// run after 600 s with a 0 and no results; this leaves a minute for the container and the
/// fallback results.json.
constexpr double kGradescopeTimeBudget = 360;
constexpr double kGradescopeTimeLimit =
    kDefaultBuildBudget + kLinkAllowance + kGradescopeTimeBudget + 20;
static_assert(kGradescopeTimeLimit + 60 <= 600, "Gradescope's default limit is 600 s");

/// a6_batch: one grading may take this long before its process group is killed (--timeout), s.
constexpr double kBatchTimeout = 900;
/// a6_batch --similarity: sim_c++ on one task file, for the whole class, s, and its address
/// space, bytes.
constexpr double kSimilaritySeconds = 120;
constexpr std::size_t kSimilarityMemoryBytes = std::size_t{2} << 30;
/// The most a rubric item's `time_limit` may be, s.
constexpr double kMaxCheckTimeLimit = 600;

// --- The list ------------------------------------------------------------------------------------

/// One limit as `a6_grade --list-limits` prints it: "key value unit  what".
struct ListedLimit {
  const char* key;
  double value;
  const char* unit;  ///< "s" or "MiB"
  const char* what;
};

inline constexpr double kMiB = 1 << 20;

inline constexpr ListedLimit kLimits[] = {
    {"build_budget", kDefaultBuildBudget, "s", "the whole build of one submission"},
    {"link_allowance", kLinkAllowance, "s", "each link, at least, past the build's budget"},
    {"compile_time", kCompileSeconds, "s", "one compile, wall clock and CPU"},
    {"compile_memory", kCompileMemoryBytes / kMiB, "MiB", "one compile's address space"},
    {"startup_time", kStartupSeconds, "s", "a probe's first answer"},
    {"time_budget", kDefaultTimeBudget, "s", "the student's code over all checks (--time-budget)"},
    {"check_time_limit", kDefaultTimeLimit, "s", "one check, where the rubric gives no time_limit"},
    {"probe_cpu", kProbeCpuSeconds, "s", "the probe's CPU time over its life"},
    {"probe_memory", kProbeMemoryBytes / kMiB, "MiB", "the probe's address space"},
    {"replay_time", kReplaySeconds, "s", "one scene's replay"},
    {"replays_time", kReplaysSeconds, "s", "all replays together"},
    {"measure_time", kMeasureSeconds, "s", "the diagnosis's designed inputs together"},
    {"own_work", kOwnWorkSeconds, "s", "the grader's own work in one grading, loaded"},
    {"max_grading", maxGradingSeconds(kDefaultTimeBudget), "s",
     "one grading's wall time at the default time budget"},
    {"gradescope_time_budget", kGradescopeTimeBudget, "s", "run_autograder's --time-budget"},
    {"gradescope_time_limit", kGradescopeTimeLimit, "s", "run_autograder stops a6_grade after"},
    {"batch_timeout", kBatchTimeout, "s", "a6_batch's --timeout: one grading"},
    {"similarity_time", kSimilaritySeconds, "s", "sim_c++ on one task file for the class"},
    {"similarity_memory", kSimilarityMemoryBytes / kMiB, "MiB", "sim_c++'s address space"},
    {"max_check_time_limit", kMaxCheckTimeLimit, "s", "the most a rubric's time_limit may be"},
};

/// `seconds` as the help texts write it: "420".
inline std::string secondsText(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", seconds);
  return text;
}

/// The lines of `a6_grade --list-limits`: "key value unit  what", one per limit.
inline std::string listedLimits() {
  std::string out;
  for (const ListedLimit& l : kLimits) {
    char line[256];
    std::snprintf(line, sizeof line, "%-22s %-5g %-3s  %s\n", l.key, l.value, l.unit, l.what);
    out += line;
  }
  return out;
}

}  // namespace a6::grader
