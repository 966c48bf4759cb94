// a6_batch: grades every submission in a folder, each by its own a6_grade (grader/batch/batch.h).
//
//   a6_batch INPUT --out DIR [-j N] [--timeout S] [--layout plain|gradescope|canvas] [--force]
//            [--grader PATH] [--rubric FILE] [--kit FILE] [--seed N] [--time-budget S]
//            [--keep-work] [--similarity [--starter DIR]]
//
// Writes DIR/<student>/ (a6_grade's results.json, report.html and grade.log; batch.json, the
// marker), DIR/gradebook.csv and DIR/insights.html; a progress bar on stderr, a summary on stdout.
// Exit status: 0 when every submission has a grade; 1 when some have none; 2 for a bad command
// line or input folder; 128+N when stopped by signal N (a re-run resumes).
//
// Runner notes
// ------------
// One a6_grade per submission, in its own process group: a crash or a hang costs that submission
// only, and --timeout kills the group. Its sandboxed children run in sessions of their own, so
// the group does not reach them: they die with it (PR_SET_PDEATHSIG, which each a6_grade gets
// too, so even `kill -9` of the batch stops its gradings). What escapes is re-parented to
// a6_grade (a child subreaper) and, once it is gone, to this process (a subreaper too): any child
// of ours that is not a running a6_grade is such a stray, and is killed.
//
// One thread: a loop starts children, reaps them, enforces the time limits and redraws the
// progress ten times a second. Signals only set a flag that the loop reads.
//
// Resume: a submission's marker (batch.json: fingerprint and outcome) is removed before it is
// graded and written last, once a6_grade has exited and its results were read; a re-run skips a
// submission whose marker holds the same fingerprint (input files, rubric, seed, time budget)
// and a grade.
//
// Other students' work: every a6_grade gets --hide for the input and the output folder (the
// sandbox binds its own work folder back), created in full before the first grading so that each
// finds them to hide. As root each claims a sandbox user of its own (grader/sandbox/process.h),
// so gradings never share a process limit and what one left running cannot touch the next. No
// compiled object is shared between submissions (it can depend on where it was compiled), only
// the kit's known objects.
//
// Reaping names each pid, never waitpid(-1), which could reap an a6_grade before the loop that
// waits for it (that batch would wait forever). One that vanishes is a grader error.
#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "batch/batch.h"
#include "batch/command_line.h"
#include "batch/progress.h"
#include "common/atomic_write.h"
#include "common/fixed.h"
#include "common/read_all.h"
#include "insights/page.h"
#include "sandbox/process.h"

namespace fs = std::filesystem;
using namespace a6::grader;
using namespace a6::grader::batch;

namespace {

using Clock = std::chrono::steady_clock;
using a6::grader::process::secondsAfter;
using a6::grader::process::secondsSince;

constexpr const char* kMarker = "batch.json";
constexpr const char* kLog = "grade.log";

volatile std::sig_atomic_t gSignal = 0;
extern "C" void onSignal(int signo) { gSignal = signo; }

const char* signalName(int signo) {
  return signo == SIGINT ? "SIGINT (Ctrl-C)" : signo == SIGTERM ? "SIGTERM" : "SIGHUP";
}

// Seconds between two sweeps for strays: 1, or A6_BATCH_SWEEP_SECONDS (the tests set it tiny, to
// provoke a sweep between a child's exit and its reaping).
double sweepInterval() {
  const char* text = std::getenv("A6_BATCH_SWEEP_SECONDS");
  const double seconds = text != nullptr ? std::atof(text) : 1.0;
  return seconds >= 0 ? seconds : 1.0;
}

struct Running {
  std::size_t index;  // into the submissions
  pid_t pid;
  Clock::time_point start;
  Clock::time_point deadline;
  bool timedOut = false;
};

class Batch {
 public:
  Batch(const Options& options, Inventory inventory, fs::path out, fs::path grader,
        std::string fingerprintOptions, int jobs)
      : o_(options),
        jobs_(jobs),
        inv_(std::move(inventory)),
        out_(std::move(out)),
        grader_(std::move(grader)),
        fingerprintOptions_(std::move(fingerprintOptions)),
        outcomes_(inv_.submissions.size()),
        skipped_(inv_.submissions.size(), false) {}

  int run() {
    const auto start = Clock::now();
    queue_ = toGrade();
    writeGradebook();
    const int skipped = static_cast<int>(std::count(skipped_.begin(), skipped_.end(), true));
    Progress progress(static_cast<int>(inv_.submissions.size()), skipped,
                      static_cast<int>(queue_.size()), jobs_, isatty(STDERR_FILENO) == 1);
    std::size_t next = 0;
    auto lastSweep = Clock::now();
    while (next < queue_.size() || !running_.empty()) {
      if (gSignal != 0) {
        progress.clear();
        return interrupted(static_cast<int>(gSignal));
      }
      while (running_.size() < static_cast<std::size_t>(jobs_) && next < queue_.size()) {
        const std::size_t i = queue_[next++];
        if (!launch(i)) finished(i, progress);
      }
      reapEnded(progress);
      enforceTimeouts();
      if (secondsSince(lastSweep) > sweepSeconds_) {
        killStrays();
        lastSweep = Clock::now();
      }
      progress.tick();
      std::this_thread::sleep_for(std::chrono::milliseconds(100));  // a signal cuts it short
    }
    progress.clear();
    killStrays();
    try {  // the page is the batch's last word, never a reason to lose its summary
      writeInsightsPage();
    } catch (const std::exception& e) {
      notes_.push_back(std::string("insights.html was not written: ") + e.what());
    }
    const int status = summary(secondsSince(start), jobs_);
    if (!similarityStopped_) return status;  // a later signal found the work done
    // A Canvas upload graded by an earlier run is not staged again (writeInsightsPage).
    const bool canvas = inv_.layout == Layout::Canvas;
    std::fprintf(stderr,
                 "a6_batch: stopped by %s during the similarity: the gradebook is complete, and "
                 "insights.html says what was not compared.\n%s\n",
                 signalName(static_cast<int>(gSignal)),
                 canvas ? "To compare a Canvas download, run the same command again with --force "
                          "(it stages only the uploads it grades: all are graded again)."
                        : "To compare, run the same command again: what was graded is skipped.");
    return 128 + static_cast<int>(gSignal);
  }

 private:
  // The submissions to grade: all but those graded already and unchanged (with --force, all).
  // Creates every student's folder first: see "Other students' work".
  std::vector<std::size_t> toGrade() {
    std::vector<std::size_t> queue;
    for (std::size_t i = 0; i < inv_.submissions.size(); ++i) {
      const Submission& s = inv_.submissions[i];
      std::error_code ec;
      fs::create_directories(out_ / s.key, ec);
      fingerprints_.push_back(fingerprint(s, fingerprintOptions_));
      if (!o_.force) {
        if (auto done = outcomeOfMarker(readAll(out_ / s.key / kMarker), fingerprints_[i]);
            done && hasGrade(*done)) {
          outcomes_[i] = *done;
          skipped_[i] = true;
          continue;
        }
      }
      queue.push_back(i);
    }
    return queue;
  }

  void finished(std::size_t i, Progress& progress) {
    progress.finished(inv_.submissions[i], *outcomes_[i]);
    writeGradebook();
  }

  void reapEnded(Progress& progress) {
    for (std::size_t k = 0; k < running_.size();) {
      bool vanished = false;
      const std::optional<int> status = process::waitFor(running_[k].pid, 0, &vanished);
      if (!status && !vanished) {
        ++k;
        continue;
      }
      const Running done = running_[k];
      running_.erase(running_.begin() + static_cast<std::ptrdiff_t>(k));
      finish(done, status, vanished);
      if (!gradedAgain(done.index)) finished(done.index, progress);
    }
  }

  // A grader error (the machine failed it: a probe that could not start, the grader killed) is
  // graded once more before the run ends; true when it was queued.
  bool gradedAgain(std::size_t i) {
    if (outcomes_[i]->status != kGraderError || regraded_.count(i) > 0) return false;
    regraded_.insert(i);
    notes_.push_back(inv_.submissions[i].key + ": graded again after a grader error (" +
                     outcomes_[i]->reason + ")");
    queue_.push_back(i);
    return true;
  }

  static void killGroup(pid_t pid) {
    kill(-pid, SIGKILL);
    kill(pid, SIGKILL);
  }

  void enforceTimeouts() {
    for (Running& r : running_) {
      if (!r.timedOut && Clock::now() >= r.deadline) {
        r.timedOut = true;
        killGroup(r.pid);
      }
    }
  }

  void failedToStart(std::size_t i, const std::string& why) {
    Outcome o;
    o.status = kGraderError;
    o.reason = why;
    outcomes_[i] = o;
    ranSeconds_.push_back(o.seconds);
  }

  // Removes what an earlier run left in a student's folder; the marker goes first, so that
  // nothing of an earlier run may pass for this one's.
  static void clearEarlierRun(const fs::path& dir) {
    std::error_code ec;
    for (const char* name : {kMarker, "results.json", "report.html", kLog}) {
      fs::remove(dir / name, ec);
    }
    fs::remove_all(dir / "work", ec);
  }

  std::vector<std::string> graderArgs(const Submission& s, const fs::path& dir) const {
    std::vector<std::string> args = {grader_.string(), s.path.string(), "--out",
                                     dir.string(),     "--jobs",        "1"};
    if (!o_.rubric.empty()) args.insert(args.end(), {"--rubric", fs::absolute(o_.rubric).string()});
    if (!o_.kit.empty()) args.insert(args.end(), {"--kit", fs::absolute(o_.kit).string()});
    if (o_.seed) args.insert(args.end(), {"--seed", std::to_string(*o_.seed)});
    if (o_.timeBudget) {
      std::ostringstream budget;
      budget << *o_.timeBudget;
      args.insert(args.end(), {"--time-budget", budget.str()});
    }
    args.insert(args.end(), {"--hide", fs::absolute(o_.input).string(), "--hide", out_.string()});
    return args;
  }

  // Starts a6_grade on submission i; false when it could not (its outcome is then set).
  bool launch(std::size_t i) {
    Submission& s = inv_.submissions[i];
    const fs::path dir = out_ / s.key;
    clearEarlierRun(dir);
    if (!s.files.empty()) {
      if (const std::string e = stage(s, dir / "submission"); !e.empty()) {
        failedToStart(i, "could not stage the files: " + e);
        return false;
      }
    }
    const std::vector<std::string> args = graderArgs(s, dir);
    const int log = ::open((dir / kLog).c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const int devnull = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (log < 0 || devnull < 0) {
      failedToStart(i, "cannot write " + (dir / kLog).string() + ": " + std::strerror(errno));
      if (log >= 0) ::close(log);
      if (devnull >= 0) ::close(devnull);
      return false;
    }
    logCommand(log, args);
    const pid_t pid = spawnGrader(args, log, devnull);
    ::close(log);
    ::close(devnull);
    if (pid < 0) {
      failedToStart(i, std::string("cannot start a6_grade: ") + std::strerror(errno));
      return false;
    }
    setpgid(pid, pid);  // here too: a time limit may kill the group before the child set it
    const auto now = Clock::now();
    running_.push_back({i, pid, now, secondsAfter(now, o_.timeout)});
    return true;
  }

  // The log opens with the command, so that a TA can run the grading again by hand.
  static void logCommand(int log, const std::vector<std::string>& args) {
    std::string command = "a6_batch ran:";
    for (const std::string& a : args) {
      const bool plain = a.find_first_not_of(
                             "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                             "0123456789-_./=:+@") == std::string::npos;
      command += " " + (plain ? a : "'" + a + "'");  // (a name with a quote is shown as is)
    }
    command += "\n";
    if (write(log, command.data(), command.size()) < 0) {
    }
  }

  // Forks a6_grade: its own process group, dead with us, default signals, stdin from /dev/null,
  // its output to the log. Returns its pid, or -1.
  static pid_t spawnGrader(std::vector<std::string> args, int log, int devnull) {
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid != 0) return pid;
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);
    for (const int signo : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) std::signal(signo, SIG_DFL);
    dup2(devnull, STDIN_FILENO);
    dup2(log, STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
    execv(argv[0], argv.data());
    const std::string why =
        std::string("a6_batch: cannot run ") + argv[0] + ": " + std::strerror(errno) + "\n";
    if (write(STDERR_FILENO, why.data(), why.size()) < 0) {
    }
    _exit(127);
  }

  // a6_grade ended (status from waitpid; none when it vanished): its outcome, marker, work folder.
  void finish(const Running& r, std::optional<int> waited, bool vanished) {
    const int status = waited.value_or(0);
    const Submission& s = inv_.submissions[r.index];
    const fs::path dir = out_ / s.key;
    const std::string seeLog = std::string(" (see ") + kLog + ")";
    Outcome o;  // a grader error unless said otherwise
    if (vanished) {
      o.reason = "a6_grade vanished: something else reaped it" + seeLog;
    } else if (r.timedOut) {
      o.status = kTimedOut;
      o.reason = "stopped after " + fixed(o_.timeout, 1) + " s (--timeout)";
    } else if (WIFSIGNALED(status)) {
      o.status = kCrashed;
      o.reason = std::string("a6_grade was killed by ") + strsignal(WTERMSIG(status)) + seeLog;
    } else {
      const int code = WEXITSTATUS(status);
      const Outcome fromResults = outcomeOfResults(readAll(dir / "results.json"));
      if (code == 0 || (code == 2 && fromResults.status == kNotGraded)) {
        o = fromResults;  // graded, or nothing to grade in it: 0 points, and why
      } else if (code == 1) {
        o.reason = !fromResults.reason.empty() && !hasGrade(fromResults)
                       ? fromResults.reason
                       : "a6_grade failed (exit status 1; see " + std::string(kLog) + ")";
      } else if (code == 2) {
        o.reason = !fromResults.reason.empty() ? fromResults.reason
                                               : "a6_grade refused its command line" + seeLog;
      } else if (code == 127) {
        o.reason = "a6_grade could not be run" + seeLog;
      } else {
        o.status = kCrashed;
        o.reason = "a6_grade exited with " + std::to_string(code) + seeLog;
      }
    }
    o.seconds = secondsSince(r.start);
    std::error_code ec;
    if (!o_.keepWork) fs::remove_all(dir / "work", ec);  // objects and the probe: megabytes
    if (hasGrade(o)) {
      if (const std::string e =
              writeFileAtomically(dir / kMarker, markerJson(fingerprints_[r.index], o));
          !e.empty()) {
        notes_.push_back(s.key + ": " + e + " (it will be graded again by a re-run)");
      }
    }
    outcomes_[r.index] = o;
    ranSeconds_.push_back(o.seconds);
  }

  // OUT/insights.html from every results.json in OUT (earlier runs' too); the similarity if asked.
  void writeInsightsPage() {
    insights::PageInput input;
    insights::SimilarityReport report;
    std::error_code ec;
    if (o_.similarity) {
      std::vector<std::pair<std::string, fs::path>> all;
      std::vector<std::string> notes;
      for (const Submission& s : inv_.submissions) {
        if (!s.path.empty()) {
          all.emplace_back(s.key, s.path);
        } else {  // a Canvas upload that this run did not stage (graded by an earlier run)
          notes.push_back(s.key + ": not compared (graded by an earlier run: --force stages it)");
        }
      }
      const fs::path work = out_ / ".similarity";
      const auto staged = insights::stageSubmissions(all, work / "files", notes);
      report = insights::compareSubmissions(staged, o_.starter, work / "compare",
                                            [] { return gSignal != 0; });
      report.notes.insert(report.notes.begin(), notes.begin(), notes.end());
      if (!o_.keepWork) fs::remove_all(work, ec);
      similarityStopped_ = report.stopped;
      input.similarity = &report;
    }
    if (const std::string e = insights::writeInsights(out_, out_ / "insights.html", input);
        !e.empty()) {
      notes_.push_back("insights.html: " + e);
    }
  }

  void writeGradebook() {
    std::vector<std::pair<const Submission*, const Outcome*>> rows;
    for (std::size_t i = 0; i < inv_.submissions.size(); ++i) {
      if (outcomes_[i]) rows.emplace_back(&inv_.submissions[i], &*outcomes_[i]);
    }
    if (const std::string e = writeFileAtomically(out_ / "gradebook.csv", gradebookCsv(rows));
        !e.empty()) {
      std::fprintf(stderr, "\na6_batch: %s\n", e.c_str());
    }
  }

  // Children of ours that are no running a6_grade: what a dead a6_grade's probe left behind.
  void killStrays() {
    std::vector<pid_t> keep;
    for (const Running& r : running_) keep.push_back(r.pid);
    process::endStrayChildren(keep);
  }

  int interrupted(int signo) {
    for (const Running& r : running_) killGroup(r.pid);
    for (const Running& r : running_) process::waitFor(r.pid, 30);
    const std::size_t stopped = running_.size();
    running_.clear();
    killStrays();
    writeGradebook();
    std::size_t graded = 0;
    for (const auto& o : outcomes_) graded += o && hasGrade(*o) ? 1 : 0;
    std::fprintf(stderr,
                 "a6_batch: stopped by %s: %zu of %zu submissions have a grade (in %s); %zu "
                 "running gradings were stopped.\n"
                 "To grade the rest, run the same command again: what was graded is skipped.\n",
                 signalName(signo), graded, inv_.submissions.size(),
                 (out_ / "gradebook.csv").c_str(), stopped);
    return 128 + signo;
  }

  // What a TA should look at for one outcome, one line each ("" for none).
  static std::string toLookAt(const std::string& key, const Outcome& o) {
    std::string lines;
    if (o.status != kGraded) {
      lines += "    " + key + ": " + o.status + (o.reason.empty() ? "" : ": " + o.reason) + "\n";
    }
    for (const std::string& flag : o.flags) {
      lines += "    " + key + ": graded, but " + flag + " (its report.html says where)\n";
    }
    return lines;
  }

  void countLines(std::ostringstream& out) const {
    std::map<std::string, int> count;  // over every outcome, whichever run graded it
    for (const auto& o : outcomes_) {
      if (o) ++count[o->status];
    }
    for (const char* status :
         {kGraded, kBuildFailed, kNotGraded, kGraderError, kTimedOut, kCrashed}) {
      out << "  " << std::left << std::setw(14) << status << std::right << std::setw(5)
          << count[status] << "\n";
    }
    const auto skipped = std::count(skipped_.begin(), skipped_.end(), true);
    out << "  " << std::left << std::setw(14) << "skipped" << std::right << std::setw(5) << skipped
        << (skipped > 0 ? "  (of the above: graded by an earlier run and unchanged; --force "
                          "regrades)"
                        : "")
        << "\n";
  }

  void timeLine(std::ostringstream& out, double wall, int jobs) const {
    out << "  batch wall time " << duration(wall) << " (" << fixed(wall, 1) << " s) with -j "
        << jobs;
    if (!ranSeconds_.empty()) {
      const double sum = std::accumulate(ranSeconds_.begin(), ranSeconds_.end(), 0.0);
      const double max = *std::max_element(ranSeconds_.begin(), ranSeconds_.end());
      out << "; per submission: mean " << fixed(sum / static_cast<double>(ranSeconds_.size()), 1)
          << " s, max " << fixed(max, 1) << " s (" << ranSeconds_.size()
          << " gradings in this run)";
    }
    out << "\n";
  }

  std::vector<std::string> allNotes() const {
    std::vector<std::string> notes = inv_.notes;
    for (const Submission& s : inv_.submissions) {
      for (const std::string& n : s.notes) notes.push_back(s.key + ": " + n);
    }
    notes.insert(notes.end(), notes_.begin(), notes_.end());
    return notes;
  }

  int summary(double wall, int jobs) {
    std::vector<double> totals;
    std::vector<const Outcome*> graded;
    std::string problems;
    for (std::size_t i = 0; i < inv_.submissions.size(); ++i) {
      if (!outcomes_[i]) continue;
      graded.push_back(&*outcomes_[i]);
      if (outcomes_[i]->total) totals.push_back(*outcomes_[i]->total);
      problems += toLookAt(inv_.submissions[i].key, *outcomes_[i]);
    }
    std::ostringstream out;
    out << "a6_batch: " << inv_.submissions.size() << " submissions in " << o_.input << " ("
        << toString(inv_.layout) << " layout), results in " << out_.string() << "\n";
    countLines(out);
    timeLine(out, wall, jobs);
    if (!totals.empty()) {
      out << "  totals (points with extra credit) of " << totals.size() << " submissions:\n"
          << histogram(totals);
    }
    if (const std::string counts = mistakeCounts(graded); !counts.empty()) {
      out << "  known mistakes named (grader/mistakes/; the gradebook's mistakes column):\n"
          << counts;
    }
    if (!problems.empty()) {
      out << "  to look at (no grade; a task file missing or broken; code that crashed, ran out "
             "of time or did not start):\n"
          << problems;
    }
    if (const std::vector<std::string> notes = allNotes(); !notes.empty()) {
      out << "  notes:\n";
      for (const std::string& n : notes) out << "    " << n << "\n";
    }
    out << "  gradebook: " << (out_ / "gradebook.csv").string() << "\n";
    out << "  the class's picture: " << (out_ / "insights.html").string() << "\n";
    std::fputs(out.str().c_str(), stdout);
    std::fflush(stdout);
    for (const auto& o : outcomes_) {
      if (!o || !hasGrade(*o)) return 1;
    }
    return 0;
  }

  const Options& o_;
  int jobs_;
  double sweepSeconds_ = sweepInterval();
  Inventory inv_;
  fs::path out_;
  fs::path grader_;
  std::string fingerprintOptions_;
  std::vector<std::optional<Outcome>> outcomes_;
  std::vector<std::string> fingerprints_;
  std::vector<Running> running_;
  std::vector<double> ranSeconds_;  // wall-clock seconds of each grading of this run
  std::vector<bool> skipped_;       // graded by an earlier run, unchanged
  std::vector<std::string> notes_;
  bool similarityStopped_ = false;  // a signal ended the comparison before its end
  std::vector<std::size_t> queue_;  // what is to be graded, in order (a grader error: again)
  std::set<std::size_t> regraded_;  // queued again after a grader error (once each)
};

// Signals only set the flag the loop reads; a dead a6_grade's strays are re-parented here.
void catchSignals() {
  std::signal(SIGPIPE, SIG_IGN);
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  for (const int signo : {SIGINT, SIGTERM, SIGHUP}) sigaction(signo, &action, nullptr);
  prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
}

int refuse(const std::string& why) {
  std::fprintf(stderr, "a6_batch: %s\n", why.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const std::optional<int> status = parseCommandLine(argc, argv, options)) return *status;
  fs::path input, out, grader;
  if (std::string why = checkPaths(options, input, out, grader); !why.empty()) return refuse(why);
  if (std::string why = checkRubric(options, grader); !why.empty()) return refuse(why);
  if (std::string why = lockOutput(out); !why.empty()) return refuse(why);

  const Layout layout =
      options.layout.empty() ? detectLayout(input, out) : *layoutNamed(options.layout);
  Inventory inventory = findSubmissions(input, layout, out);
  if (!inventory.error.empty()) return refuse(inventory.error);
  if (inventory.submissions.empty()) {
    for (const std::string& n : inventory.notes) std::fprintf(stderr, "  %s\n", n.c_str());
    return refuse("no submission found in " + options.input + " (read as the " + toString(layout) +
                  " layout; --layout chooses another)");
  }
  catchSignals();
  options.input = input.string();
  const int jobs = options.jobs > 0
                       ? options.jobs
                       : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  Batch batch(options, std::move(inventory), out, grader, decidingOptions(options), jobs);
  return batch.run();
}
