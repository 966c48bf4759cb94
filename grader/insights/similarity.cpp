// Code similarity with sim_c++. See similarity.h. Per task file: (1) each submission's copy, the
// starter's lines blanked, into work/<task file>/<n>.cpp; (2) sim_c++ -e -s -n: the runs two files
// share; (3) per file and line, the other files sharing it (more than kCommonShare: common);
// (4) per pair, the share of each file's own code the other has; the larger decides (one file
// may hold all of the other and more).
#include "insights/similarity.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <system_error>

#include "common/limits.h"
#include "common/read_all.h"
#include "harness/tasks.h"
#include "intake/intake.h"
#include "sandbox/process.h"

namespace a6::grader::insights {
namespace {

namespace fs = std::filesystem;

constexpr const char* kTool = "sim_c++";
constexpr std::uintmax_t kLargestFile = 64 << 10;  // bytes: a task file is a few kB
constexpr int kMinimumRareLines = 4;               // fewer shared rare lines: a coincidence

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// A line that is code: not blank, not a comment alone.
bool isCode(const std::string& line) {
  const std::string t = trimmed(line);
  return !t.empty() && t.rfind("//", 0) != 0 && t.rfind("/*", 0) != 0 && t.rfind("*", 0) != 0;
}

// The tool's wait status; none when it ran out of time, `stop` asked, or it vanished (then its
// pid may be another process's by then: not to be killed).
std::optional<int> waitUnlessStopped(pid_t pid, const StopAsked& stop, bool& vanished) {
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    if (const std::optional<int> status = process::waitFor(pid, 0.2, &vanished)) return status;
    if (vanished || process::secondsSince(start) >= kSimilaritySeconds || stop()) return {};
  }
}

// Runs sim_c++ with `args` into `out`; true when it ended in time and was not stopped.
bool runTool(std::vector<std::string> args, const fs::path& out, const StopAsked& stop) {
  args.insert(args.begin(), kTool);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_RDWR);
    const int report = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (null < 0 || report < 0) _exit(126);
    dup2(null, STDIN_FILENO);
    dup2(report, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    // The files are the students': the tool gets bounded time, memory and output.
    const rlimit cpu{static_cast<rlim_t>(kSimilaritySeconds),
                     static_cast<rlim_t>(kSimilaritySeconds)};
    const rlimit memory{kSimilarityMemoryBytes, kSimilarityMemoryBytes},
        output{rlim_t(64) << 20, rlim_t(64) << 20};
    setrlimit(RLIMIT_CPU, &cpu);
    setrlimit(RLIMIT_AS, &memory);
    setrlimit(RLIMIT_FSIZE, &output);
    execvp(kTool, argv.data());
    _exit(127);
  }
  if (pid < 0) return false;
  bool vanished = false;
  std::optional<int> status = waitUnlessStopped(pid, stop, vanished);
  if (!status && !vanished) {
    kill(pid, SIGKILL);
    status = process::waitFor(pid, 5);
  }
  return status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0;
}

// sim_c++ -v: "Version 3.0.2 ...": the tool's name and version; "" when it does not run.
std::string toolVersion(const fs::path& work, const StopAsked& stop) {
  const fs::path out = work / "version.txt";
  if (!runTool({"-v"}, out, stop)) return "";
  const std::vector<std::string> lines = linesOf(readAll(out));
  return std::string(kTool) + " (Debian's similarity-tester" +
         (lines.empty() ? std::string(")") : ", " + trimmed(lines.front()) + ")");
}

struct Run {
  int a = 0, b = 0;  // file indexes
  int a0 = 0, a1 = 0, b0 = 0, b1 = 0, tokens = 0;
};

// "work/spring.cpp/3.cpp: line 4-8   |work/spring.cpp/5.cpp: line 4-10  [39]".
std::vector<Run> parseRuns(const std::string& report) {
  static const std::regex line(
      R"(^.*/(\d+)\.cpp: line (\d+)-(\d+)\s*\|.*/(\d+)\.cpp: line (\d+)-(\d+)\s*\[(\d+)\]\s*$)");
  std::vector<Run> runs;
  for (const std::string& l : linesOf(report)) {
    std::smatch m;
    if (!std::regex_match(l, m, line)) continue;
    runs.push_back({std::stoi(m[1]), std::stoi(m[4]), std::stoi(m[2]), std::stoi(m[3]),
                    std::stoi(m[5]), std::stoi(m[6]), std::stoi(m[7])});
  }
  return runs;
}

// One task file of one submission, prepared for the tool.
struct Prepared {
  std::size_t submission = 0;
  std::vector<std::string> lines;    // the submission's own text
  std::vector<std::string> blanked;  // the starter's lines blanked
};

// The submissions' copies of `taskFile` that differ from the starter, starter lines blanked.
std::vector<Prepared> prepare(const std::vector<SubmissionFiles>& subs, const fs::path& starterDir,
                              const std::string& taskFile, std::vector<std::string>& notes) {
  const std::string starter = readAll(starterDir / taskFile);
  if (starter.empty())
    notes.push_back(taskFile + ": no starter file in " + starterDir.string() +
                    ": nothing of it discounted");
  std::set<std::string> starterLines;
  for (const std::string& l : linesOf(starter)) starterLines.insert(trimmed(l));
  std::vector<Prepared> all;
  for (std::size_t i = 0; i < subs.size(); ++i) {
    const fs::path file = subs[i].folder / taskFile;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) continue;
    if (fs::file_size(file, ec) > kLargestFile) {
      notes.push_back(subs[i].key + ": " + taskFile + " is over 64 kB: not compared");
      continue;
    }
    const std::string text = readAll(file);
    if (text == starter) continue;
    Prepared p{i, linesOf(text), {}};
    for (const std::string& l : p.lines)
      p.blanked.push_back(starterLines.count(trimmed(l)) ? "" : l);
    all.push_back(std::move(p));
  }
  return all;
}

// For each file and line, the other files sharing it.
using Cover = std::vector<std::vector<std::set<int>>>;

Cover coverOf(const std::vector<Prepared>& files, const std::vector<Run>& runs) {
  Cover cover(files.size());
  for (std::size_t i = 0; i < files.size(); ++i) cover[i].resize(files[i].lines.size() + 1);
  auto mark = [&](int file, int first, int last, int other) {
    auto& lines = cover[static_cast<std::size_t>(file)];
    for (int l = std::max(first, 1); l <= last && l < static_cast<int>(lines.size()); ++l)
      lines[static_cast<std::size_t>(l)].insert(other);
  };
  for (const Run& r : runs) {
    if (r.a < 0 || r.b < 0 || r.a >= static_cast<int>(files.size()) ||
        r.b >= static_cast<int>(files.size()))
      continue;
    mark(r.a, r.a0, r.a1, r.b);
    mark(r.b, r.b0, r.b1, r.a);
  }
  return cover;
}

// Of file i's own code, the share file j has too, and how many lines that is. A line is common,
// not i's own, when more than kCommonShare of the files other than i and j share it (j is left
// out: a pair that copied must not hide behind itself).
std::pair<double, int> rareShare(const std::vector<Prepared>& files, const Cover& cover, int i,
                                 int j) {
  const double common = kCommonShare * static_cast<double>(files.size() - 2);
  int own = 0, shared = 0;
  const auto& f = files[static_cast<std::size_t>(i)];
  for (std::size_t l = 1; l <= f.blanked.size(); ++l) {
    if (!isCode(f.blanked[l - 1])) continue;
    const auto& who = cover[static_cast<std::size_t>(i)][l];
    const bool withJ = who.count(j) > 0;
    const double others = static_cast<double>(who.size()) - (withJ ? 1 : 0);
    if (others > common && files.size() > 2) continue;
    ++own;
    shared += withJ;
  }
  return {own == 0 ? 0.0 : double(shared) / own, shared};
}

std::string linesText(const std::vector<std::string>& lines, int first, int last) {
  std::string text;
  for (int l = std::max(first, 1); l <= last && l <= static_cast<int>(lines.size()); ++l)
    text += lines[static_cast<std::size_t>(l - 1)] + "\n";
  return text;
}

SimilarPair pairOf(const std::vector<SubmissionFiles>& subs, const std::vector<Prepared>& files,
                   const std::vector<Run>& runs, int i, int j, const std::string& taskFile,
                   int percent) {
  const Prepared &pa = files[static_cast<std::size_t>(i)], &pb = files[static_cast<std::size_t>(j)];
  SimilarPair p{subs[pa.submission].key, subs[pb.submission].key, taskFile, percent, {}};
  for (const Run& r : runs) {
    if (!((r.a == i && r.b == j) || (r.a == j && r.b == i))) continue;
    const bool ab = r.a == i;
    SharedPassage s{
        ab ? r.a0 : r.b0, ab ? r.a1 : r.b1, ab ? r.b0 : r.a0, ab ? r.b1 : r.a1, r.tokens, "", ""};
    s.textA = linesText(pa.lines, s.firstA, s.lastA);
    s.textB = linesText(pb.lines, s.firstB, s.lastB);
    p.passages.push_back(std::move(s));
  }
  std::sort(p.passages.begin(), p.passages.end(),
            [](const SharedPassage& x, const SharedPassage& y) { return x.firstA < y.firstA; });
  if (p.a > p.b) {
    std::swap(p.a, p.b);
    for (SharedPassage& s : p.passages) {
      std::swap(s.firstA, s.firstB);
      std::swap(s.lastA, s.lastB);
      std::swap(s.textA, s.textB);
    }
  }
  return p;
}

// False when `stop` ended the comparison before its end.
bool compareTaskFile(const std::vector<SubmissionFiles>& subs, const fs::path& starter,
                     const fs::path& work, const std::string& taskFile, SimilarityReport& report,
                     const StopAsked& stop) {
  std::vector<Prepared> files = prepare(subs, starter, taskFile, report.notes);
  if (files.size() < 2) return true;
  const fs::path dir = work / taskFile;
  fs::create_directories(dir);
  std::vector<std::string> args = {"-r", std::to_string(report.minimumRun), "-e", "-s", "-n"};
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::ofstream(dir / (std::to_string(i) + ".cpp")) << linesText(files[i].blanked, 1, 1 << 30);
    args.push_back((dir / (std::to_string(i) + ".cpp")).string());
  }
  if (!runTool(args, dir / "report.txt", stop)) {
    if (stop()) return false;
    report.notes.push_back(taskFile + ": " + kTool + " failed or ran out of time: not compared");
    return true;
  }
  report.compared += static_cast<int>(files.size());
  const std::vector<Run> runs = parseRuns(readAll(dir / "report.txt"));
  const Cover cover = coverOf(files, runs);
  for (int i = 0; i < static_cast<int>(files.size()); ++i) {
    for (int j = i + 1; j < static_cast<int>(files.size()); ++j) {
      const auto [ij, linesIj] = rareShare(files, cover, i, j);
      const auto [ji, linesJi] = rareShare(files, cover, j, i);
      const double share = std::max(ij, ji);
      if (std::min(linesIj, linesJi) < kMinimumRareLines || 100 * share < report.threshold)
        continue;
      report.pairs.push_back(
          pairOf(subs, files, runs, i, j, taskFile, static_cast<int>(100 * share + 0.5)));
    }
  }
  return true;
}

// The report stopped at task file `from`: it and the task files after it were not compared.
void stoppedAt(const std::string& from, SimilarityReport& report) {
  std::string names;
  const auto first = std::find(kTaskFiles.begin(), kTaskFiles.end(), from);
  for (auto it = first; it != kTaskFiles.end(); ++it) names += (names.empty() ? "" : ", ") + *it;
  report.stopped = true;
  report.notes.push_back("the comparison was stopped before its end: " + names + " not compared");
}

}  // namespace

std::vector<SubmissionFiles> stageSubmissions(
    const std::vector<std::pair<std::string, fs::path>>& keyAndPath, const fs::path& work,
    std::vector<std::string>& notes) {
  std::error_code ec;
  fs::remove_all(work, ec);
  std::vector<SubmissionFiles> staged;
  for (std::size_t i = 0; i < keyAndPath.size(); ++i) {
    const auto& [key, path] = keyAndPath[i];
    const fs::path dest = work / std::to_string(i);
    const Intake intake = takeSubmission(path, dest);
    if (!intake.ok()) {
      notes.push_back(key + ": not compared: " + intake.error);
      continue;
    }
    if (!intake.files.empty()) staged.push_back({key, dest});
  }
  return staged;
}

SimilarityReport compareSubmissions(const std::vector<SubmissionFiles>& submissions,
                                    const fs::path& starter, const fs::path& work,
                                    const StopAsked& stopAsked, int threshold, int minimumRun) {
  const StopAsked stop = stopAsked ? stopAsked : [] { return false; };
  SimilarityReport report;
  report.threshold = threshold;
  report.minimumRun = minimumRun;
  std::error_code ec;
  fs::remove_all(work, ec);
  fs::create_directories(work, ec);
  report.tool = toolVersion(work, stop);
  if (stop()) {
    stoppedAt(kTaskFiles.front(), report);
    return report;
  }
  if (report.tool.empty()) {
    report.notes.push_back(std::string(kTool) +
                           " is not installed (Debian's similarity-tester: "
                           "scripts/install-deps.sh installs it): nothing was compared");
    return report;
  }
  for (const std::string& taskFile : kTaskFiles) {
    try {
      if (stop() || !compareTaskFile(submissions, starter, work, taskFile, report, stop)) {
        stoppedAt(taskFile, report);
        break;
      }
    } catch (const std::exception& e) {
      report.notes.push_back(taskFile + ": " + e.what());
    }
  }
  std::stable_sort(
      report.pairs.begin(), report.pairs.end(),
      [](const SimilarPair& a, const SimilarPair& b) { return a.percent > b.percent; });
  return report;
}

}  // namespace a6::grader::insights
