// a6_batch: grading a folder of submissions.
//
//   BatchParts.*   the pieces, on small inputs: Gradescope's metadata, Canvas's file names,
//                  CSV quoting, the outcome of a results.json, markers, fingerprints;
//   Batch.*        the command, end to end with the real a6_grade: a batch of every submission
//                  whose score we know (the solution, the starter, every wrong version, every
//                  hostile and broken one, a corrupt archive, an empty folder) checked row by
//                  row in gradebook.csv; an interrupted batch that resumes; --force; the
//                  Gradescope and Canvas layouts; gradings that hang, crash or fail (a fake
//                  grader); a submission that tries to read another; bad command lines.
//
// Each Batch case is its own ctest entry (grader_batch_<case>), so they run in parallel.
#include "batch/batch.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "report/report.h"
#include "rubric/rubric.h"
#include "run_command.h"
#include "sandbox/process.h"
#include "staging.h"

namespace {

namespace fs = std::filesystem;
namespace batch = a6::grader::batch;
namespace staging = a6::test::staging;
using a6::test::staging::kSource;
using a6::test::staging::kTaskFiles;
using a6::test::staging::readAll;
using a6::test::staging::writeAll;
using nlohmann::json;

// ---- running a6_batch ---------------------------------------------------------------------------

using Ran = a6::test::CommandRun;

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

Ran run(const std::string& command) { return a6::test::runCommand(command); }

Ran batchRun(const fs::path& input, const fs::path& out, const std::string& extra = "") {
  return run(std::string(A6_BATCH_COMMAND) + " " + quoted(input) + " --out " + quoted(out) + " " +
             extra);
}

// This case's folder, inside the build tree (ctest's working directory), emptied.
fs::path caseDir(const std::string& name) {
  const fs::path dir = fs::absolute("batch_out") / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A summary line's count: "  graded   12".
int counted(const std::string& output, const std::string& status) {
  std::smatch m;
  if (!std::regex_search(output, m, std::regex("\n  " + status + " +([0-9]+)"))) return -1;
  return std::stoi(m[1].str());
}

// ---- gradebook.csv ------------------------------------------------------------------------------

struct Gradebook {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  std::string error;
  const std::map<std::string, std::string>* row(const std::string& student) const {
    for (const auto& r : rows) {
      if (r.at("student") == student) return &r;
    }
    return nullptr;
  }
};

// RFC 4180: fields quoted when needed, "" for a quote, CRLF between records.
std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> records(1);
  std::string field;
  bool inQuotes = false, any = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inQuotes) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        inQuotes = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      inQuotes = any = true;
    } else if (c == ',') {
      records.back().push_back(field);
      field.clear();
    } else if (c == '\r' || c == '\n') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      records.back().push_back(field);
      field.clear();
      records.emplace_back();
    } else {
      field += c;
      any = true;
    }
  }
  if (!field.empty() || !records.back().empty()) records.back().push_back(field);
  if (records.back().empty()) records.pop_back();
  (void)any;
  return records;
}

const std::vector<std::string> kHeader = {
    "student", "email", "sid",   "total", "max",          "task1",  "task2",   "task3",
    "task4",   "task5", "task6", "task7", "extra_credit", "status", "seconds", "mistakes"};

Gradebook readGradebook(const fs::path& file) {
  Gradebook g;
  const auto records = parseCsv(readAll(file));
  if (records.empty()) {
    g.error = "empty gradebook " + file.string();
    return g;
  }
  g.header = records[0];
  for (std::size_t i = 1; i < records.size(); ++i) {
    if (records[i].size() != g.header.size()) {
      g.error = "row " + std::to_string(i) + " has " + std::to_string(records[i].size()) +
                " fields, the header " + std::to_string(g.header.size());
      return g;
    }
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < g.header.size(); ++k) row[g.header[k]] = records[i][k];
    g.rows.push_back(row);
  }
  return g;
}

std::optional<double> number(const std::string& field) {
  if (field.empty()) return std::nullopt;
  try {
    return std::stod(field);
  } catch (...) {
    return std::nullopt;
  }
}

double pointsOf(const std::map<std::string, std::string>& row, const std::string& column) {
  const auto x = number(row.at(column));
  EXPECT_TRUE(x.has_value()) << column << " of " << row.at("student") << " is '" << row.at(column)
                             << "'";
  return x.value_or(-1);
}

std::string describe(const std::map<std::string, std::string>& row) {
  std::string text;
  for (const std::string& column : kHeader) {
    const auto it = row.find(column);
    text += column + "=" + (it == row.end() ? "?" : it->second) + " ";
  }
  return text;
}

// ---- processes ----------------------------------------------------------------------------------

// Processes whose command line mentions `text` (a6_grade with --out under a case's folder).
std::vector<std::string> processesMentioning(const std::string& text) {
  std::vector<std::string> found;
  std::error_code ec;
  for (fs::directory_iterator it("/proc", ec), end; !ec && it != end; it.increment(ec)) {
    const std::string pid = it->path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if (std::stol(pid) == getpid()) continue;
    std::string cmdline = readAll(it->path() / "cmdline");
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    if (cmdline.find(text) != std::string::npos) found.push_back(pid + " " + cmdline);
  }
  return found;
}

void expectNoProcessMentioning(const std::string& text) {
  std::vector<std::string> left;
  for (int k = 0; k < 30; ++k) {  // the kernel reaps within moments
    left = processesMentioning(text);
    if (left.empty()) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  std::string list;
  for (const std::string& p : left) {
    list += p + "\n";
    kill(static_cast<pid_t>(std::stol(p)), SIGKILL);
  }
  ADD_FAILURE() << "processes outlived the batch:\n" << list;
}

// a6_batch started in the background, its output to a file.
pid_t startBatch(const fs::path& input, const fs::path& out, const fs::path& log,
                 const std::vector<std::string>& extra) {
  std::vector<std::string> args = {A6_BATCH_COMMAND, input.string(), "--out", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    FILE* f = std::fopen(log.c_str(), "w");
    if (f != nullptr) {
      dup2(fileno(f), STDOUT_FILENO);
      dup2(fileno(f), STDERR_FILENO);
    }
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

int markers(const fs::path& out) {
  int n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(out, ec)) n += fs::exists(e.path() / "batch.json");
  return n;
}

// Waits until `out` holds at least `n` markers (true), or `seconds` pass (false).
bool waitForMarkers(const fs::path& out, int n, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (markers(out) >= n) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

// ---- the rubric ---------------------------------------------------------------------------------

const a6::grader::Rubric& rubric() {
  static const a6::grader::Rubric r = a6::grader::loadRubric(A6_DEFAULT_RUBRIC);
  return r;
}

// The rubric's regular points per task (1..6) and its extra credit per task.
std::map<int, double> rubricPoints(bool extraCredit) {
  std::map<int, double> points;
  for (const auto& item : rubric().items) {
    if (item.extraCredit == extraCredit) points[item.task] += item.points;
  }
  return points;
}

// =================================================================================================
// The pieces
// =================================================================================================

TEST(BatchParts, GradescopeMetadataGivesEachSubmissionItsSubmitters) {
  // As Gradescope writes it (Ruby symbols, quoted sids, a group, data the batch skips; a block
  // scalar whose text looks like keys).
  const std::string yaml = R"(---
submission_409194023:
  :submitters:
  - :name: First Last
    :sid: '123456789'
    :email: first@example.edu
  :created_at: 2026-04-26 17:34:00.861687000 Z
  :score: 2.0
  :results:
    score: 2.0
    output: |-
      :submitters:
      - :name: Not A Student
submission_500000001:
  :submitters:
    - :email: "alice@example.edu"
      :name: 'O''Brien, Alice'
      :sid: 111
    - :name: Bob B # a comment
      :sid: '222'
  :score: 10.0
  :history:
  - :created_at: 2026-04-25 10:00:00.000000000 Z
    :score: 5.0
submission_600000002:
  :submitters: []
)";
  const auto m = batch::parseGradescopeMetadata(yaml);
  ASSERT_EQ(m.size(), 3u);
  ASSERT_EQ(m.at("submission_409194023").size(), 1u) << "the block scalar is not a submitter";
  const batch::Person& first = m.at("submission_409194023")[0];
  EXPECT_EQ(first.name, "First Last");
  EXPECT_EQ(first.sid, "123456789");
  EXPECT_EQ(first.email, "first@example.edu");
  const auto& group = m.at("submission_500000001");
  ASSERT_EQ(group.size(), 2u) << "the history is not a submitter";
  EXPECT_EQ(group[0].name, "O'Brien, Alice");
  EXPECT_EQ(group[0].email, "alice@example.edu");
  EXPECT_EQ(group[0].sid, "111");
  EXPECT_EQ(group[1].name, "Bob B");
  EXPECT_EQ(group[1].sid, "222");
  EXPECT_TRUE(m.at("submission_600000002").empty());
  // Not YAML, or nested past the parser's depth: no submission named, and no crash.
  for (const std::string& bad : {std::string("a: [1\n"), std::string(100000, '['),
                                 std::string("\x01\xff\0garbage", 10), std::string("- a\n- b\n")}) {
    EXPECT_TRUE(batch::parseGradescopeMetadata(bad).empty()) << bad.substr(0, 20);
  }
}

TEST(BatchParts, CanvasNamesGiveTheStudentAndTheOriginalName) {
  const auto a = batch::parseCanvasName("doejane_1234_5678_spring.cpp");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->login, "doejane");
  EXPECT_EQ(a->userId, "1234");
  EXPECT_EQ(a->submissionId, "5678");
  EXPECT_EQ(a->original, "spring.cpp");
  EXPECT_FALSE(a->late);
  EXPECT_EQ(a->reupload, 0);

  const auto b = batch::parseCanvasName("doejane_LATE_1234_5679_spring-1.cpp");
  ASSERT_TRUE(b);
  EXPECT_TRUE(b->late);
  EXPECT_EQ(b->original, "spring.cpp");
  EXPECT_EQ(b->reupload, 1);

  const auto c = batch::parseCanvasName("smithjohn_42_77_my_work-2.tar.gz");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->original, "my_work.tar.gz") << "underscores of the original name are kept";
  EXPECT_EQ(c->reupload, 2);

  EXPECT_FALSE(batch::parseCanvasName("notes.txt"));
  EXPECT_FALSE(batch::parseCanvasName("doejane_spring.cpp"));
  EXPECT_FALSE(batch::parseCanvasName("doejane_12a_5678_spring.cpp"));
}

TEST(BatchParts, SafeNamesNeverLeaveTheFolder) {
  EXPECT_EQ(batch::safeName("Jane Doe"), "Jane_Doe");
  EXPECT_EQ(batch::safeName("../../etc"), "etc");
  EXPECT_EQ(batch::safeName("..."), "student");
  EXPECT_EQ(batch::safeName(""), "student");
  EXPECT_EQ(batch::safeName("a/b\\c"), "a_b_c");
}

// Outcomes for the gradebook's cases: a group's grade (with two known mistakes) and a grading
// that timed out.
batch::Outcome gradedWithMistakes() {
  batch::Outcome graded;
  graded.status = batch::kBuildFailed;
  graded.total = 88.5;
  graded.max = 100;
  graded.tasks = {15, 15, 20, 3.5, 15, 20, std::nullopt};
  graded.extraCredit = 0;
  graded.seconds = 2.25;
  graded.mistakes = {"t1_wrong_sign", "t4_duplicate_springs"};
  return graded;
}

batch::Outcome timedOut() {
  batch::Outcome o;
  o.status = batch::kTimedOut;
  return o;
}

TEST(BatchParts, TheGradebookIsValidCsv) {
  EXPECT_EQ(batch::csvField("plain"), "plain");
  EXPECT_EQ(batch::csvField("Doe, Jane"), "\"Doe, Jane\"");
  EXPECT_EQ(batch::csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(batch::csvField("two\nlines"), "\"two\nlines\"");

  batch::Submission s;
  s.key = "group";
  s.people = {{"Doe, Jane", "jane@example.edu", "1"}, {"Bob \"B\"", "", "2"}};
  const batch::Outcome graded = gradedWithMistakes();
  batch::Submission t;
  t.key = "hung";
  t.people = {{"hung", "", ""}};
  const batch::Outcome hung = timedOut();
  const std::string csv = batch::gradebookCsv({{&s, &graded}, {&t, &hung}});
  const auto records = parseCsv(csv);
  ASSERT_EQ(records.size(), 4u) << csv;
  EXPECT_EQ(records[0], kHeader);
  EXPECT_EQ(records[1][0], "Doe, Jane");
  EXPECT_EQ(records[2][0], "Bob \"B\"");
  // The column named `name`.
  const auto at = [](const std::vector<std::string>& record, const std::string& name) {
    const auto i = std::find(kHeader.begin(), kHeader.end(), name) - kHeader.begin();
    return i < static_cast<std::ptrdiff_t>(record.size()) ? record[static_cast<std::size_t>(i)]
                                                          : "(no " + name + ")";
  };
  EXPECT_EQ(at(records[1], "total"), "88.5");
  EXPECT_EQ(at(records[1], "task4"), "3.5");
  EXPECT_EQ(at(records[1], "status"), "build failed");
  EXPECT_EQ(at(records[3], "total"), "") << "no points without a grade";
  EXPECT_EQ(at(records[3], "status"), "timed out");
  EXPECT_EQ(at(records[1], "mistakes"), "t1_wrong_sign t4_duplicate_springs");
  EXPECT_EQ(at(records[3], "mistakes"), "");
  for (const auto& r : records) EXPECT_EQ(r.size(), kHeader.size()) << csv;
}

TEST(BatchParts, TheSummaryCountsTheMistakesAndDrawsTheScores) {
  // How many submissions made each known mistake, most often first.
  const batch::Outcome graded = gradedWithMistakes(), hung = timedOut();
  batch::Outcome other;
  other.mistakes = {"t4_duplicate_springs"};
  const std::string counts = batch::mistakeCounts({&graded, &other, &hung});
  EXPECT_LT(counts.find("t4_duplicate_springs"), counts.find("t1_wrong_sign")) << counts;
  EXPECT_NE(counts.find("2 submissions"), std::string::npos) << counts;
  EXPECT_NE(counts.find("1 submission\n"), std::string::npos) << counts;
  EXPECT_EQ(batch::mistakeCounts({&hung}), "");
  // Read from results.json's extra_data.mistakes.
  const batch::Outcome read = batch::outcomeOfResults(
      R"({"score": 5, "tests": [], "extra_data": {"errors": [], "build": {},
          "mistakes": [{"task": 1, "mistake": "t1_wrong_sign", "evidence": 6}]}})");
  EXPECT_EQ(read.mistakes, std::vector<std::string>{"t1_wrong_sign"});

  const std::string h = batch::histogram({0, 5, 9.99, 10, 103});
  EXPECT_NE(h.find("0-9 | ### 3"), std::string::npos) << h;
  EXPECT_NE(h.find("10-19 | # 1"), std::string::npos) << h;
  EXPECT_NE(h.find("100-109 | # 1"), std::string::npos) << h;
}

// The results.json a6_grade writes (report.cpp's resultsJson), read back: per-task points by
// the tests' tags, extra credit apart, and a task that did not compile.
TEST(BatchParts, TheOutcomeOfAResultsJson) {
  using namespace a6::grader;
  GradeReport report;
  report.maxScore = 30;
  auto item = [](const std::string& name, int task, double points, bool extra) {
    RubricItem i;
    i.name = name;
    i.task = task;
    i.points = points;
    i.extraCredit = extra;
    return i;
  };
  report.items.push_back({item("Task 1: spring", 1, 15, false), 15, 1, 0, {}, "1.1"});
  report.items.push_back({item("Task 4 extra credit", 4, 3, true), 3, 1, 0, {}, "4.1"});
  report.items.push_back({item("Task 4: cloth", 4, 15, false), 7.5, 1, 1, {}, "4.2"});
  report.score = 25.5;
  report.extraCredit = 3;
  for (const std::string& file : kTaskFiles) {
    TaskBuild t;
    t.file = file;
    t.status = file == "cloth.cpp" ? TaskBuild::Status::CompileError : TaskBuild::Status::Compiled;
    report.build.tasks.push_back(t);
  }
  batch::Outcome o = batch::outcomeOfResults(resultsJson(report));
  EXPECT_EQ(o.status, batch::kBuildFailed);
  EXPECT_NE(o.reason.find("cloth.cpp did not compile"), std::string::npos) << o.reason;
  ASSERT_TRUE(o.total && o.max && o.extraCredit && o.tasks[0] && o.tasks[3] && o.tasks[5]);
  EXPECT_DOUBLE_EQ(*o.total, 25.5);
  EXPECT_DOUBLE_EQ(*o.max, 30);
  EXPECT_DOUBLE_EQ(*o.tasks[0], 15);
  EXPECT_DOUBLE_EQ(*o.tasks[3], 7.5) << "the extra credit is not task 4's";
  EXPECT_DOUBLE_EQ(*o.tasks[5], 0);
  EXPECT_DOUBLE_EQ(*o.extraCredit, 3);

  report.build.tasks[3].status = TaskBuild::Status::Compiled;
  EXPECT_EQ(batch::outcomeOfResults(resultsJson(report)).status, batch::kGraded);

  // a6_grade's placeholder (it was killed), an invalid file, no file.
  report.errors = {"grading did not finish (the grader was killed or ran out of time)"};
  o = batch::outcomeOfResults(resultsJson(report));
  EXPECT_EQ(o.status, batch::kGraderError);
  EXPECT_FALSE(o.hasPoints());
  EXPECT_NE(o.reason.find("did not finish"), std::string::npos);
  EXPECT_EQ(batch::outcomeOfResults("{\"score\": ").status, batch::kGraderError);
  EXPECT_EQ(batch::outcomeOfResults("").status, batch::kGraderError);
}

TEST(BatchParts, AMarkerHoldsTheOutcomeForItsFingerprintOnly) {
  batch::Outcome o;
  o.status = batch::kGraded;
  o.total = 103;
  o.max = 100;
  o.tasks = {15, 15, 20, 15, 15, 20, std::nullopt};
  o.extraCredit = 3;
  o.seconds = 1.5;
  o.mistakes = {"t3_missing_pinning"};
  const std::string marker = batch::markerJson("0123456789abcdef", o);
  const auto back = batch::outcomeOfMarker(marker, "0123456789abcdef");
  ASSERT_TRUE(back);
  EXPECT_EQ(back->status, o.status);
  EXPECT_EQ(back->total, o.total);
  EXPECT_EQ(back->tasks, o.tasks);
  EXPECT_EQ(back->extraCredit, o.extraCredit);
  EXPECT_EQ(back->mistakes, o.mistakes);
  EXPECT_FALSE(batch::outcomeOfMarker(marker, "fedcba9876543210"));
  EXPECT_FALSE(batch::outcomeOfMarker(marker.substr(0, marker.size() / 2), "0123456789abcdef"));
}

TEST(BatchParts, TheFingerprintChangesWithAFileOrTheOptions) {
  const fs::path dir = caseDir("fingerprint");
  writeAll(dir / "alice" / "spring.cpp", "one");
  writeAll(dir / "alice" / "sub" / "forces.cpp", "two");
  batch::Submission s;
  s.path = dir / "alice";
  const std::string a = batch::fingerprint(s, "rubric=1");
  EXPECT_EQ(batch::fingerprint(s, "rubric=1"), a);
  EXPECT_NE(batch::fingerprint(s, "rubric=2"), a);
  writeAll(dir / "alice" / "sub" / "forces.cpp", "tw0");
  EXPECT_NE(batch::fingerprint(s, "rubric=1"), a) << "a changed file deeper down";
  writeAll(dir / "alice" / "sub" / "forces.cpp", "two");
  EXPECT_EQ(batch::fingerprint(s, "rubric=1"), a);
  fs::rename(dir / "alice" / "sub" / "forces.cpp", dir / "alice" / "sub" / "Forces.cpp");
  EXPECT_NE(batch::fingerprint(s, "rubric=1"), a) << "a renamed file";
}

TEST(BatchParts, LayoutsAreRecognisedAndUnknownEntriesNoted) {
  const fs::path dir = caseDir("layouts");
  writeAll(dir / "plain" / "alice" / "spring.cpp", "x");
  writeAll(dir / "plain" / "bob.tar.gz", "x");
  writeAll(dir / "plain" / "notes.txt", "x");
  writeAll(dir / "gs" / "assignment_1_export" / "submission_metadata.yml",
           "submission_1:\n  :submitters:\n  - :name: Jane Doe\n");
  writeAll(dir / "gs" / "assignment_1_export" / "submission_1" / "spring.cpp", "x");
  writeAll(dir / "canvas" / "doejane_1_2_spring.cpp", "x");
  writeAll(dir / "canvas" / "doejane_1_3_forces.cpp", "x");
  writeAll(dir / "canvas" / ".DS_Store", "x");
  EXPECT_EQ(batch::detectLayout(dir / "plain"), batch::Layout::Plain);
  EXPECT_EQ(batch::detectLayout(dir / "gs"), batch::Layout::Gradescope);
  EXPECT_EQ(batch::detectLayout(dir / "canvas"), batch::Layout::Canvas);

  const auto plain =
      batch::findSubmissions(dir / "plain", batch::Layout::Plain, dir / "plain" / "alice");
  ASSERT_EQ(plain.submissions.size(), 1u) << "the excluded folder (the output) is no submission";
  EXPECT_EQ(plain.submissions[0].key, "bob");
  ASSERT_EQ(plain.notes.size(), 1u);
  EXPECT_NE(plain.notes[0].find("notes.txt"), std::string::npos);

  const auto gs = batch::findSubmissions(dir / "gs", batch::Layout::Gradescope);
  ASSERT_EQ(gs.submissions.size(), 1u) << gs.error;
  EXPECT_EQ(gs.submissions[0].key, "Jane_Doe");
  EXPECT_EQ(gs.submissions[0].people[0].name, "Jane Doe");

  const auto canvas = batch::findSubmissions(dir / "canvas", batch::Layout::Canvas);
  ASSERT_EQ(canvas.submissions.size(), 1u);
  EXPECT_EQ(canvas.submissions[0].files.size(), 2u);
  EXPECT_EQ(canvas.notes.size(), 1u) << ".DS_Store is noted";
}

// =================================================================================================
// The command
// =================================================================================================

TEST(Batch, ABadCommandLineOrInputExitsWith2) {
  const fs::path dir = caseDir("bad");
  Ran r = batchRun("/nonexistent/submissions", dir / "out");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("no such folder: /nonexistent/submissions"), std::string::npos)
      << r.output;
  writeAll(dir / "export.zip", "x");
  r = batchRun(dir / "export.zip", dir / "out");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("not a folder"), std::string::npos) << r.output;
  fs::create_directories(dir / "nothing");
  r = batchRun(dir / "nothing", dir / "out");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("no submission found"), std::string::npos) << r.output;
  EXPECT_EQ(run(A6_BATCH_COMMAND).status, 2);
  r = batchRun(dir / "nothing", dir / "out", "--layout moodle");
  EXPECT_EQ(r.status, 2) << r.output;
  r = batchRun(dir / "nothing", dir / "out", "--grader /nonexistent/a6_grade");
  EXPECT_EQ(r.status, 2) << r.output;
  const Ran help = run(std::string(A6_BATCH_COMMAND) + " --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.output.find("--timeout"), std::string::npos) << help.output;
}

// ---- a class of every kind ---------------------------------------------------------------------

// The submissions of GradesOneOfEveryKindOfSubmission, and the rubric's points they are held to.
struct Class {
  std::set<std::string> students;        ///< every submission's row name
  std::vector<std::string> wrong;        ///< the wrong versions among them (without "wrong_")
  std::map<int, double> regular, extra;  ///< the rubric's points per task
  double full = 0, fullExtra = 0;        ///< and in all
};

// The solution, the starter, and one wrong version with a named mistake, for the gradebook's
// mistakes column and task columns (every wrong version is graded on its own by its ctest entry,
// wrong_<name>).
void stageKnownScores(const fs::path& in, Class& c) {
  fs::create_directories(in);
  fs::copy(kSource / "solution", in / "solution", fs::copy_options::recursive);
  c.students.insert("solution");
  fs::copy(kSource / "starter", in / "starter", fs::copy_options::recursive);
  c.students.insert("starter");
  for (const std::string& name : staging::wrongVersions()) {
    if (c.wrong.empty() && !staging::expectedMistake(name).empty()) c.wrong.push_back(name);
  }
  ASSERT_EQ(c.wrong.size(), 1u) << "no wrong version has a named mistake";
  for (const std::string& name : c.wrong) {
    staging::stageWrong(in / ("wrong_" + name), name);
    c.students.insert("wrong_" + name);
  }
}

// Hostile submissions, the archive cases, a damaged archive, an empty folder, a stray file.
void stageHostileOnes(const fs::path& in, Class& c) {
  // (Not the fork bomb, nor the endless loop in the tasks' code: with this test's 2 s limit they
  // cost their whole time budget, 2 minutes, and grader_hostile_* grade them on their own, the
  // loop with fewer checks of task 1. Of the code that ends or hangs before main, only the hang:
  // an exit or an abort there is the same "build failed" row, each graded on its own by
  // grader_hostile_*.)
  const std::set<std::string> hostile = {"compile_error", "missing_file",  "static_infinite_loop",
                                         "segfault",      "huge_output",   "write_files",
                                         "nan",           "symlink_folder"};
  for (const std::string& fixture : staging::fixtures()) {
    if (hostile.count(fixture) == 0) continue;
    staging::stage(in / ("hostile_" + fixture), fixture, {}, staging::omittedBy(fixture));
    c.students.insert("hostile_" + fixture);
  }
  ASSERT_EQ(std::count_if(c.students.begin(), c.students.end(),
                          [](const std::string& s) { return s.rfind("hostile_", 0) == 0; }),
            static_cast<std::ptrdiff_t>(hostile.size()))
      << "a hostile fixture of this test is gone from tests/grader/submissions";
  for (const staging::ArchiveCase& a : staging::archiveCases()) {
    const std::string ext = a.zip() ? ".zip" : ".tar.gz";
    ASSERT_EQ(staging::writeArchive(in / ("hostile_" + a.name + ext), a.zip(), a.entries), "");
    c.students.insert("hostile_" + a.name);
  }
  // A damaged archive (cut inside its first file's data, so that no task file is whole), an
  // empty folder, and something that is no submission at all.
  std::string zip = readAll(in / "hostile_zip_traversal.zip");
  writeAll(in / "corrupt.zip", zip.substr(0, 100) + std::string(200, '\x7f'));
  c.students.insert("corrupt");
  fs::create_directories(in / "empty");
  c.students.insert("empty");
  writeAll(in / "README.txt", "submissions downloaded on Monday");
}

// The solution: every point and the extra credit, and no mistake; the wrong version: its own
// mistake, in its row and in the summary's counts; the starter: nothing.
void expectSolutionAndStarterRows(const Gradebook& g, const Class& c, const std::string& output) {
  const auto* solution = g.row("solution");
  ASSERT_NE(solution, nullptr);
  EXPECT_EQ(solution->at("status"), "graded") << describe(*solution);
  EXPECT_DOUBLE_EQ(pointsOf(*solution, "total"), c.full + c.fullExtra) << describe(*solution);
  EXPECT_DOUBLE_EQ(pointsOf(*solution, "max"), c.full);
  EXPECT_DOUBLE_EQ(pointsOf(*solution, "extra_credit"), c.fullExtra);
  EXPECT_GT(c.fullExtra, 0);
  EXPECT_EQ(solution->at("mistakes"), "") << describe(*solution);
  for (const std::string& name : c.wrong) {
    const auto* row = g.row("wrong_" + name);
    const std::string id = staging::expectedMistake(name);
    if (row == nullptr || id.empty()) continue;
    EXPECT_EQ(row->at("mistakes"), id) << describe(*row);
    EXPECT_NE(output.find(id), std::string::npos) << "the summary counts " << id;
  }
  for (int t = 1; t <= 7; ++t) {
    EXPECT_DOUBLE_EQ(pointsOf(*solution, "task" + std::to_string(t)),
                     c.regular.count(t) ? c.regular.at(t) : 0)
        << t;
  }
  const auto* starter = g.row("starter");
  ASSERT_NE(starter, nullptr);
  EXPECT_EQ(starter->at("status"), "graded");
  EXPECT_DOUBLE_EQ(pointsOf(*starter, "total"), 0) << describe(*starter);
}

// The class's picture: every submission, every rubric item, the wrong version's mistake, the
// similarity compared (the wrong version is the solution with one file changed).
void expectInsightsPage(const fs::path& out, const Class& c) {
  const std::string page = readAll(out / "insights.html");
  ASSERT_FALSE(page.empty()) << "no insights.html";
  for (const std::string& st : c.students) {
    EXPECT_NE(page.find("<td>" + st + "</td>"), std::string::npos) << "insights.html lacks " << st;
  }
  for (const auto& item : rubric().items) {
    EXPECT_NE(page.find(item.name), std::string::npos) << "insights.html lacks " << item.name;
  }
  for (const std::string& name : c.wrong) {
    EXPECT_NE(page.find("<code>" + staging::expectedMistake(name) + "</code>"), std::string::npos);
  }
  EXPECT_NE(page.find("sim_c++ (Debian"), std::string::npos) << "--similarity ran no tool";
  EXPECT_EQ(page.find(", 0 files compared"), std::string::npos) << "--similarity compared nothing";
  EXPECT_FALSE(fs::exists(out / ".similarity")) << "the comparison's work is left";
}

// Each wrong version loses points in exactly the tasks its EXPECT names. The extra credit (one
// column for tasks 4 and 7) belongs to its task: it may be what a wrong version loses there. The
// gradebook has a column for each task's regular points (task 7's are none with the default
// rubric: it is extra credit).
void expectWrongVersionRows(const Gradebook& g, const Class& c) {
  for (const std::string& name : c.wrong) {
    const auto* row = g.row("wrong_" + name);
    ASSERT_NE(row, nullptr) << name;
    EXPECT_EQ(row->at("status"), "graded") << describe(*row);
    const std::set<int> failing = staging::failingTasks(name);
    const bool extraShort = pointsOf(*row, "extra_credit") < c.fullExtra;
    bool extraLost = false;
    for (int t = 1; t <= 7; ++t) {
      const double got = pointsOf(*row, "task" + std::to_string(t));
      const double taskRegular = c.regular.count(t) ? c.regular.at(t) : 0;
      const double taskExtra = c.extra.count(t) ? c.extra.at(t) : 0;
      if (failing.count(t)) {
        EXPECT_TRUE(got < taskRegular || (taskExtra > 0 && extraShort))
            << name << " must lose points in task " << t << ": " << describe(*row);
        extraLost = extraLost || taskExtra > 0;
      } else {
        EXPECT_DOUBLE_EQ(got, taskRegular)
            << name << " must keep every point of task " << t << ": " << describe(*row);
      }
    }
    if (!extraLost) {
      EXPECT_DOUBLE_EQ(pointsOf(*row, "extra_credit"), c.fullExtra)
          << name << ": " << describe(*row);
    }
  }
}

// Every hostile or broken one has a grade, never more than the solution's; those with a task
// file missing or broken say "build failed"; those with no task file, "not graded".
void expectHostileRows(const Gradebook& g, const Class& c, const fs::path& out,
                       const std::string& output) {
  const std::set<std::string> buildFails = {"hostile_compile_error", "hostile_missing_file",
                                            "hostile_static_infinite_loop"};
  const std::set<std::string> notGraded = {"empty"};
  // A damaged archive: libarchive 3.6 (Debian 12) reads the entries before the damage (build
  // failed), 3.7 (Debian 13) none of it (not graded). Either way no grade above 0.
  const std::set<std::string> damaged = {"corrupt"};
  for (const std::string& s : c.students) {
    if (s.rfind("hostile_", 0) != 0 && s != "corrupt" && s != "empty") continue;
    const auto* row = g.row(s);
    ASSERT_NE(row, nullptr) << s;
    EXPECT_TRUE(row->at("status") == "graded" || row->at("status") == "build failed" ||
                row->at("status") == "not graded")
        << describe(*row);
    EXPECT_LE(pointsOf(*row, "total"), c.full + c.fullExtra) << describe(*row);
    if (buildFails.count(s)) {
      EXPECT_EQ(row->at("status"), "build failed") << describe(*row);
    }
    if (notGraded.count(s)) {
      EXPECT_EQ(row->at("status"), "not graded") << describe(*row);
    }
    // Each is listed for a TA to look at, the crash too though it was graded.
    if (damaged.count(s)) {
      EXPECT_TRUE(row->at("status") == "build failed" || row->at("status") == "not graded")
          << describe(*row);
    }
    if (buildFails.count(s) || notGraded.count(s) || damaged.count(s) || s == "hostile_segfault") {
      EXPECT_NE(output.find("\n    " + s + ": "), std::string::npos) << s << "\n" << output;
    }
    EXPECT_TRUE(fs::exists(out / s / "results.json")) << s;
    EXPECT_TRUE(fs::exists(out / s / "report.html")) << s;
    EXPECT_TRUE(fs::exists(out / s / "grade.log")) << s;
    EXPECT_FALSE(fs::exists(out / s / "work")) << "the work folder is removed";
  }
  EXPECT_DOUBLE_EQ(pointsOf(*g.row("corrupt"), "total"), 0);
  EXPECT_DOUBLE_EQ(pointsOf(*g.row("empty"), "total"), 0);
  EXPECT_NE(output.find("hostile_segfault: graded, but the code crashed"), std::string::npos)
      << output;
}

// A class of every kind in one batch with -j 2, checked row by row: the solution, the starter,
// one wrong version of each task, hostile submissions that break the build or hang the probe
// before main (and those a batch must keep apart: one that writes files, one that floods its
// output), the archive cases, a damaged archive, an empty folder, a stray file. Every wrong
// version and every hostile submission is graded on its own by the grader_scores_* and
// grader_hostile_* tests; here the batch must keep each one's row right beside the others.
TEST(Batch, GradesOneOfEveryKindOfSubmission) {
  const fs::path dir = caseDir("everything");
  const fs::path in = dir / "submissions";
  Class c;
  stageKnownScores(in, c);
  if (HasFatalFailure()) return;
  stageHostileOnes(in, c);
  if (HasFatalFailure()) return;
  ASSERT_GE(c.students.size(), 16u);

  // Short time limits for the cases that never return (the correct checks take hundredths of
  // a second): the endless loop costs task 1's checks 2 s each.
  const fs::path rubricFile = staging::withTimeLimit(A6_DEFAULT_RUBRIC, dir, 2);
  const Ran r =
      batchRun(in, dir / "out",
               "-j 2 --timeout 600 --time-budget 120 --similarity --rubric " + quoted(rubricFile));
  std::printf("%s", r.output.substr(r.output.find("a6_batch: ")).c_str());
  EXPECT_EQ(r.status, 0) << "every submission has a grade\n" << r.output;
  EXPECT_NE(r.output.find("README.txt"), std::string::npos) << "the stray file is noted";
  EXPECT_EQ(counted(r.output, "graded") + counted(r.output, "build failed") +
                counted(r.output, "not graded"),
            static_cast<int>(c.students.size()))
      << r.output;

  // A row for everyone, then each kind's.
  const Gradebook g = readGradebook(dir / "out" / "gradebook.csv");
  ASSERT_EQ(g.error, "");
  EXPECT_EQ(g.header, kHeader);
  EXPECT_EQ(g.rows.size(), c.students.size());
  for (const std::string& s : c.students) EXPECT_NE(g.row(s), nullptr) << "no row for " << s;
  ASSERT_TRUE(rubric().ok()) << rubric().error;
  c.regular = rubricPoints(false);
  c.extra = rubricPoints(true);
  for (const auto& [task, p] : c.regular) c.full += p;
  for (const auto& [task, p] : c.extra) c.fullExtra += p;
  expectSolutionAndStarterRows(g, c, r.output);
  if (HasFatalFailure()) return;
  expectInsightsPage(dir / "out", c);
  if (HasFatalFailure()) return;
  expectWrongVersionRows(g, c);
  if (HasFatalFailure()) return;
  expectHostileRows(g, c, dir / "out", r.output);
  if (HasFatalFailure()) return;
  expectNoProcessMentioning(dir.string());
}

// ---- an interrupted batch ----------------------------------------------------------------------

// Starts a batch of `total` submissions and kills it (kill -9) once two are graded: its
// children die with it, and what it left is a valid gradebook of what it finished. Gives the
// markers of the graded ones.
void startAndKill(const fs::path& dir, const fs::path& in, const fs::path& out, int total,
                  std::map<std::string, std::string>& graded) {
  const pid_t pid = startBatch(in, out, dir / "first.log", {"-j", "2"});
  ASSERT_GT(pid, 0);
  const bool some = waitForMarkers(out, 2, 120);
  kill(pid, SIGKILL);
  int raw = 0;
  waitpid(pid, &raw, 0);
  ASSERT_TRUE(some) << readAll(dir / "first.log");
  EXPECT_TRUE(WIFSIGNALED(raw));
  // Its a6_grade children die with it (PR_SET_PDEATHSIG).
  expectNoProcessMentioning(out.string());
  const int done = markers(out);
  ASSERT_LT(done, total) << "the batch finished before it was killed: nothing to resume";
  for (const auto& e : fs::directory_iterator(out)) {
    if (fs::exists(e.path() / "batch.json")) {
      graded[e.path().filename().string()] = readAll(e.path() / "batch.json");
    }
  }
  const Gradebook partial = readGradebook(out / "gradebook.csv");
  EXPECT_EQ(partial.error, "");
  EXPECT_EQ(partial.header, kHeader);
  EXPECT_GE(static_cast<int>(partial.rows.size()), done - 1);
}

// Run again: what was graded (its marker unchanged) is skipped, the rest graded, and the
// gradebook complete.
void expectItResumes(const fs::path& in, const fs::path& out, int total,
                     const std::map<std::string, std::string>& graded) {
  const Ran second = batchRun(in, out, "-j 2");
  EXPECT_EQ(second.status, 0) << second.output;
  EXPECT_EQ(counted(second.output, "skipped"), static_cast<int>(graded.size())) << second.output;
  // The counts are over every submission, whichever run graded it.
  EXPECT_EQ(counted(second.output, "graded"), total) << second.output;
  for (const auto& [student, marker] : graded) {
    EXPECT_EQ(readAll(out / student / "batch.json"), marker) << student << " was graded again";
  }
  const Gradebook complete = readGradebook(out / "gradebook.csv");
  ASSERT_EQ(complete.error, "");
  EXPECT_EQ(complete.rows.size(), static_cast<std::size_t>(total));
  ASSERT_NE(complete.row("solution"), nullptr);
  const auto& solution = *complete.row("solution");
  EXPECT_EQ(solution.at("status"), "graded");
  EXPECT_DOUBLE_EQ(pointsOf(solution, "total"),
                   pointsOf(solution, "max") + pointsOf(solution, "extra_credit"));
}

// Nothing changed: nothing graded; one submission changed: it alone is graded again; --force:
// everything.
void expectOnlyChangesAreGradedAgain(const fs::path& in, const fs::path& out, int total) {
  Ran third = batchRun(in, out, "-j 2");
  EXPECT_EQ(counted(third.output, "skipped"), total) << third.output;
  writeAll(in / "starter" / "spring.cpp", readAll(kSource / "solution" / "spring.cpp"));
  third = batchRun(in, out, "-j 2");
  EXPECT_EQ(counted(third.output, "graded"), total) << third.output;
  EXPECT_EQ(counted(third.output, "skipped"), total - 1) << third.output;
  EXPECT_GT(pointsOf(*readGradebook(out / "gradebook.csv").row("starter"), "task1"), 0)
      << "the changed spring.cpp was graded";
  const Ran forced = batchRun(in, out, "-j 2 --force");
  EXPECT_EQ(forced.status, 0) << forced.output;
  EXPECT_EQ(counted(forced.output, "graded"), total) << forced.output;
  EXPECT_EQ(counted(forced.output, "skipped"), 0) << forced.output;
  EXPECT_EQ(readGradebook(out / "gradebook.csv").rows.size(), static_cast<std::size_t>(total));
}

// Killed half-way (kill -9: no chance to clean up), then run again: what was graded is skipped,
// the rest is graded, and the gradebook ends complete. A changed submission is graded again;
// --force grades everything again.
TEST(Batch, AnInterruptedBatchResumesWithWhatIsLeft) {
  const fs::path dir = caseDir("resume");
  const fs::path in = dir / "submissions", out = dir / "out";
  fs::create_directories(in);
  fs::copy(kSource / "solution", in / "solution", fs::copy_options::recursive);
  fs::copy(kSource / "starter", in / "starter", fs::copy_options::recursive);
  // Two more that lose some points: the solution with the starter's file of task 2, of task 5.
  staging::stage(in / "no_task2", "", {2});
  staging::stage(in / "no_task5", "", {5});
  const int total = 4;

  std::map<std::string, std::string> graded;  // the graded ones' markers
  startAndKill(dir, in, out, total, graded);
  if (HasFatalFailure()) return;
  expectItResumes(in, out, total, graded);
  if (HasFatalFailure()) return;
  expectOnlyChangesAreGradedAgain(in, out, total);
}

// SIGTERM (or Ctrl-C): the running gradings are stopped, the gradebook holds what finished, and
// the message says how to resume.
TEST(Batch, SigtermStopsTheGradingsAndSaysHowToResume) {
  const fs::path dir = caseDir("sigterm");
  const fs::path in = dir / "submissions", out = dir / "out";
  for (const char* name : {"a", "b", "c", "d", "e", "f"}) {
    fs::create_directories(in);
    fs::copy(kSource / "solution", in / name, fs::copy_options::recursive);
  }
  const pid_t pid = startBatch(in, out, dir / "log", {"-j", "2"});
  ASSERT_TRUE(waitForMarkers(out, 1, 120)) << readAll(dir / "log");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the next gradings start
  kill(pid, SIGTERM);
  int raw = 0;
  waitpid(pid, &raw, 0);
  const std::string log = readAll(dir / "log");
  ASSERT_TRUE(WIFEXITED(raw)) << log;
  EXPECT_EQ(WEXITSTATUS(raw), 128 + SIGTERM) << log;
  EXPECT_NE(log.find("run the same command again"), std::string::npos) << log;
  std::smatch stopped;
  ASSERT_TRUE(std::regex_search(log, stopped, std::regex("([0-9]+) running gradings were stopped")))
      << log;
  EXPECT_GE(std::stoi(stopped[1].str()), 1) << log;
  expectNoProcessMentioning(out.string());
  const Gradebook g = readGradebook(out / "gradebook.csv");
  EXPECT_EQ(g.error, "");
  EXPECT_EQ(static_cast<int>(g.rows.size()), markers(out)) << "a row per graded submission";
  for (const auto& row : g.rows) EXPECT_EQ(row.at("status"), "graded") << describe(row);
}

// Ctrl-C while the similarity runs (sim_c++ may take minutes on a class): the comparison stops
// at once, the page says what was not compared, and the message says how to finish. A fake
// grader (instant) and a fake sim_c++ (it hangs, after leaving a mark) play the parts.
TEST(Batch, CtrlCDuringTheSimilarityStopsItAndSaysWhatWasNotCompared) {
  const fs::path dir = caseDir("sigint_similarity");
  const fs::path in = dir / "submissions", out = dir / "out", bin = dir / "bin";
  for (const char* name : {"a", "b"}) {
    writeAll(in / name / "spring.cpp", readAll(kSource / "solution" / "spring.cpp"));
  }
  writeAll(dir / "fake_grade.sh", R"SH(#!/bin/sh
mkdir -p "$3"; echo '{"score": 1, "tests": [], "extra_data": {"errors": []}}' > "$3/results.json"
)SH");
  const std::string sim = R"SH(#!/bin/sh
[ "$1" = -v ] && { echo 'Version 3.0.2 (a fake)'; exit 0; }
touch 'MARK'; exec sleep 419
)SH";
  writeAll(bin / "sim_c++",
           a6::test::staging::replaceAll(sim, "MARK", (dir / "comparing").string()));
  for (const fs::path& p : {dir / "fake_grade.sh", bin / "sim_c++"})
    fs::permissions(p, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
  const char* pathNow = std::getenv("PATH");
  const std::string path = pathNow != nullptr ? pathNow : "/usr/bin:/bin";
  setenv("PATH", (bin.string() + ":" + path).c_str(), 1);
  const pid_t pid = startBatch(in, out, dir / "log",
                               {"--similarity", "--grader", (dir / "fake_grade.sh").string()});
  setenv("PATH", path.c_str(), 1);
  for (int i = 0; i < 6000 && !fs::exists(dir / "comparing"); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const bool comparing = fs::exists(dir / "comparing");
  kill(pid, comparing ? SIGINT : SIGKILL);
  ASSERT_TRUE(comparing) << readAll(dir / "log");
  // At once: sim_c++ alone would take 120 s for each of the task files.
  const std::optional<int> ended = a6::grader::process::waitFor(pid, 60);
  const std::string log = readAll(dir / "log");
  if (!ended) {  // kill it, and the tool it would leave
    kill(pid, SIGKILL);
    a6::grader::process::waitFor(pid, 10);
    expectNoProcessMentioning("sleep 419");
  }
  ASSERT_TRUE(ended) << "still comparing 60 s after Ctrl-C\n" << log;
  const int raw = *ended;
  ASSERT_TRUE(WIFEXITED(raw)) << log;
  EXPECT_EQ(WEXITSTATUS(raw), 128 + SIGINT) << log;
  EXPECT_NE(log.find("stopped by SIGINT (Ctrl-C) during the similarity"), std::string::npos) << log;
  EXPECT_NE(log.find("run the same command again"), std::string::npos) << log;
  EXPECT_EQ(readGradebook(out / "gradebook.csv").rows.size(), 2u) << "the gradebook is complete";
  const std::string page = readAll(out / "insights.html");
  EXPECT_NE(page.find("the comparison was stopped before its end: spring.cpp, forces.cpp"),
            std::string::npos);
  EXPECT_NE(page.find(", 0 files compared"), std::string::npos) << "none was compared";
  EXPECT_EQ(page.find("No pair above the threshold"), std::string::npos) << "it was not compared";
  expectNoProcessMentioning("sleep 419");
}

// ---- gradings that hang, crash or fail
// -----------------------------------------------------------

// A fake a6_grade that plays each part by the submission's name: hangs (with a child of its
// own), crashes, fails, writes garbage, refuses; any other gets `results`, whose rows test the
// task columns (task 7 counted as regular points by an instructor's rubric).
fs::path writeMisbehavingGrader(const fs::path& dir) {
  writeAll(dir / "results.json", R"({"score": 49, "tests": [
    {"name": "Task 1", "score": 12, "max_score": 15, "tags": ["task1"]},
    {"name": "Task 4 extra", "score": 3, "max_score": 0, "tags": ["task4", "extra_credit"]},
    {"name": "Task 6", "score": 30, "max_score": 75, "tags": ["task6"]},
    {"name": "Task 7 counted as regular points", "score": 4, "max_score": 10, "tags": ["task7"]}],
    "extra_data": {"max_score": 100, "extra_credit": 3, "errors": [],
                   "build": {"spring.cpp": "compiled"}}})");
  // The grader's arguments: SUBMISSION --out DIR --jobs 1 ... (the rest is not read).
  const std::string script = R"SH(#!/bin/sh
out="$3"; mkdir -p "$out"
case "$(basename "$1")" in
  hangs*) sleep 417 & sleep 417 ;;
  crashes) kill -SEGV $$ ;;
  fails) echo '{"score": 0, "tests": [], "extra_data": {"errors": ["the kit is missing"]}}' \
           > "$out/results.json"; exit 1 ;;
  garbage) echo '{"score": ' > "$out/results.json" ;;
  refused) exit 2 ;;
  *) cp 'RESULTS' "$out/results.json" ;;
esac
)SH";
  const fs::path grader = dir / "fake_grade.sh";
  writeAll(grader,
           a6::test::staging::replaceAll(script, "RESULTS", (dir / "results.json").string()));
  fs::permissions(grader, fs::perms::owner_all);
  return grader;
}

// Each one's status, no points without a grade, the graded one's points by column, and the
// hung one killed at the time limit.
void expectEachStatus(const Gradebook& g, const Ran& r) {
  const std::map<std::string, std::string> expected = {
      {"fine", "graded"},         {"hangs", "timed out"},    {"hangs_too", "timed out"},
      {"crashes", "crashed"},     {"fails", "grader error"}, {"garbage", "grader error"},
      {"refused", "grader error"}};
  for (const auto& [student, status] : expected) {
    const auto* row = g.row(student);
    ASSERT_NE(row, nullptr) << student;
    EXPECT_EQ(row->at("status"), status) << describe(*row);
    if (status != "graded") {
      EXPECT_EQ(row->at("total"), "") << "no points without a grade: " << describe(*row);
    }
  }
  const auto* fine = g.row("fine");
  EXPECT_DOUBLE_EQ(pointsOf(*fine, "total"), 49);
  EXPECT_DOUBLE_EQ(pointsOf(*fine, "task1"), 12);
  EXPECT_DOUBLE_EQ(pointsOf(*fine, "task4"), 0);
  EXPECT_DOUBLE_EQ(pointsOf(*fine, "task6"), 30);
  EXPECT_DOUBLE_EQ(pointsOf(*fine, "task7"), 4) << "an instructor's rubric may count task 7";
  EXPECT_DOUBLE_EQ(pointsOf(*fine, "extra_credit"), 3);
  const double hung = pointsOf(*g.row("hangs"), "seconds");
  EXPECT_GE(hung, 2.9);
  EXPECT_LT(hung, 10) << "killed at the time limit";
  EXPECT_NE(r.output.find("the kit is missing"), std::string::npos) << r.output;
}

// A grading that hangs is killed at --timeout (with what it started), one that crashes or fails
// is recorded, and the batch goes on: a fake grader plays each part.
TEST(Batch, HangingCrashingAndFailingGradingsAreRecordedAndTheBatchGoesOn) {
  const fs::path dir = caseDir("statuses");
  const fs::path in = dir / "submissions", out = dir / "out";
  for (const char* name :
       {"fine", "hangs", "hangs_too", "crashes", "fails", "garbage", "refused"}) {
    writeAll(in / name / "spring.cpp", "// " + std::string(name));
  }
  const fs::path grader = writeMisbehavingGrader(dir);
  const Ran r = batchRun(in, out, "-j 3 --timeout 3 --grader " + quoted(grader));
  EXPECT_EQ(r.status, 1) << "some submissions have no grade\n" << r.output;
  EXPECT_LT(r.seconds, 60) << r.output;
  const Gradebook g = readGradebook(out / "gradebook.csv");
  ASSERT_EQ(g.error, "");
  ASSERT_EQ(g.rows.size(), 7u) << r.output;
  expectEachStatus(g, r);
  if (HasFatalFailure()) return;
  expectNoProcessMentioning("sleep 417");  // the whole process group was killed

  // Only what has a grade is skipped by a re-run: the others are tried again.
  const Ran again = batchRun(in, out, "-j 3 --timeout 3 --grader " + quoted(grader));
  EXPECT_EQ(counted(again.output, "skipped"), 1) << again.output;
  expectNoProcessMentioning("sleep 417");
}

// The race that hung a batch overnight: an a6_grade that exits between the loop's reaping and a
// sweep for strays was reaped by the sweep, and the batch waited for it forever. Provoked here:
// gradings that take no time (a script), a sweep at every turn of the loop, more jobs than
// cores, five batches in a row; each must end, with every submission graded.
TEST(Batch, AGradingThatEndsDuringASweepIsStillCounted) {
  const fs::path dir = caseDir("sweep_race");
  const fs::path in = dir / "submissions", out = dir / "out";
  constexpr int kSubmissions = 40;
  for (int k = 0; k < kSubmissions; ++k) {
    writeAll(in / ("s" + std::to_string(k)) / "spring.cpp", "// tiny");
  }
  writeAll(dir / "results.json", R"({"score": 1, "tests": [],
    "extra_data": {"max_score": 100, "extra_credit": 0, "errors": [], "build": {}}})");
  const fs::path grader = dir / "instant_grade.sh";
  writeAll(grader, "#!/bin/sh\nmkdir -p \"$3\" && cp '" + (dir / "results.json").string() +
                       "' \"$3/results.json\"\n");
  fs::permissions(grader, fs::perms::owner_all);
  for (int round = 0; round < 5; ++round) {
    const Ran r =
        run("A6_BATCH_SWEEP_SECONDS=0 timeout -s KILL 120 " + std::string(A6_BATCH_COMMAND) + " " +
            quoted(in) + " --out " + quoted(out) + " -j 4 --force --grader " + quoted(grader));
    ASSERT_EQ(r.status, 0) << "round " << round << " (137: the batch hung and was killed)\n"
                           << r.output;
    EXPECT_EQ(counted(r.output, "graded"), kSubmissions) << r.output;
  }
}

// A grading killed from outside while the batch runs costs its own submission only.
TEST(Batch, AGradingKilledFromOutsideIsRecordedAndTheBatchGoesOn) {
  const fs::path dir = caseDir("killed_outside");
  const fs::path in = dir / "submissions", out = dir / "out";
  for (const char* name : {"a", "b", "victim", "c"}) writeAll(in / name / "spring.cpp", "// x");
  writeAll(dir / "results.json", R"({"score": 2, "tests": [],
    "extra_data": {"max_score": 100, "extra_credit": 0, "errors": [], "build": {}}})");
  const std::string script = R"SH(#!/bin/sh
out="$3"; mkdir -p "$out"
if [ "$(basename "$1")" = victim ]; then echo $$ > 'PIDFILE'; exec sleep 300; fi
cp 'RESULTS' "$out/results.json"
)SH";
  const fs::path pidFile = dir / "victim.pid";
  const fs::path grader = dir / "fake_grade.sh";
  writeAll(grader, a6::test::staging::replaceAll(
                       a6::test::staging::replaceAll(script, "PIDFILE", pidFile.string()),
                       "RESULTS", (dir / "results.json").string()));
  fs::permissions(grader, fs::perms::owner_all);
  std::thread killer([&] {
    for (int k = 0; k < 600 && !fs::exists(pidFile); ++k) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const std::string pid = readAll(pidFile);
    if (!pid.empty()) kill(static_cast<pid_t>(std::stol(pid)), SIGKILL);
  });
  const Ran r = run("timeout -s KILL 120 " + std::string(A6_BATCH_COMMAND) + " " + quoted(in) +
                    " --out " + quoted(out) + " -j 2 --grader " + quoted(grader));
  killer.join();
  EXPECT_EQ(r.status, 1) << "one submission has no grade\n" << r.output;
  const Gradebook g = readGradebook(out / "gradebook.csv");
  ASSERT_EQ(g.error, "");
  ASSERT_EQ(g.rows.size(), 4u) << r.output;
  EXPECT_EQ(g.row("victim")->at("status"), "crashed") << describe(*g.row("victim"));
  for (const char* name : {"a", "b", "c"}) EXPECT_EQ(g.row(name)->at("status"), "graded");
}

// Gradescope's "Export Submissions", unzipped: the metadata names the students (a group gets a
// row per member).
TEST(Batch, AGradescopeExportIsRecognised) {
  const fs::path dir = caseDir("gradescope");
  const fs::path root = dir / "export" / "assignment_4242_export";
  fs::create_directories(root);
  fs::copy(kSource / "solution", root / "submission_1001", fs::copy_options::recursive);
  fs::copy(kSource / "starter", root / "submission_1002", fs::copy_options::recursive);
  a6::test::staging::stage(root / "submission_1003", "", {1});
  writeAll(root / "submission_metadata.yml", R"(---
submission_1001:
  :submitters:
  - :name: Jane Doe
    :sid: '1001'
    :email: jane@example.edu
  :created_at: 2026-04-26 17:34:00.861687000 Z
  :score: 0.0
submission_1002:
  :submitters:
  - :name: Bob Smith
    :sid: '1002'
    :email: bob@example.edu
  - :name: Carol Jones
    :sid: '1003'
    :email: carol@example.edu
  :score: 0.0
submission_1003:
  :submitters:
  - :name: Dan Brown
    :sid: '1004'
    :email: dan@example.edu
)");
  const Ran r = batchRun(dir / "export", dir / "out", "-j 2");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("gradescope layout"), std::string::npos) << r.output;
  const Gradebook g = readGradebook(dir / "out" / "gradebook.csv");
  ASSERT_EQ(g.error, "");
  ASSERT_EQ(g.rows.size(), 4u) << "a row per student, the group's two included\n" << r.output;
  const auto* jane = g.row("Jane Doe");
  ASSERT_NE(jane, nullptr);
  EXPECT_EQ(jane->at("email"), "jane@example.edu");
  EXPECT_EQ(jane->at("sid"), "1001");
  EXPECT_DOUBLE_EQ(pointsOf(*jane, "total"),
                   pointsOf(*jane, "max") + pointsOf(*jane, "extra_credit"));
  for (const char* member : {"Bob Smith", "Carol Jones"}) {
    const auto* row = g.row(member);
    ASSERT_NE(row, nullptr) << member;
    EXPECT_DOUBLE_EQ(pointsOf(*row, "total"), 0) << describe(*row);
  }
  EXPECT_EQ(g.row("Carol Jones")->at("sid"), "1003");
  const auto* dan = g.row("Dan Brown");
  ASSERT_NE(dan, nullptr);
  EXPECT_LT(pointsOf(*dan, "task1"), pointsOf(*jane, "task1")) << describe(*dan);
  EXPECT_DOUBLE_EQ(pointsOf(*dan, "task2"), pointsOf(*jane, "task2")) << describe(*dan);
  EXPECT_TRUE(fs::exists(dir / "out" / "Jane_Doe" / "results.json"));
  EXPECT_TRUE(fs::exists(dir / "out" / "Bob_Smith-Carol_Jones" / "report.html"));
}

// Canvas's "Download Submissions", unzipped: one flat folder; each student's files are staged
// under their original names (the latest of a re-uploaded file), or their one zip is graded.
TEST(Batch, ACanvasDownloadIsRecognised) {
  const fs::path dir = caseDir("canvas");
  const fs::path in = dir / "download";
  fs::create_directories(in);
  // doejane uploads the seven files one by one; spring.cpp twice (the starter's first).
  int id = 5000;
  for (const std::string& file : kTaskFiles) {
    fs::copy_file(kSource / "solution" / file,
                  in / ("doejane_1234_" + std::to_string(++id) + "_" + file));
  }
  fs::remove(in / "doejane_1234_5001_spring.cpp");
  fs::copy_file(kSource / "starter" / "spring.cpp", in / "doejane_1234_5001_spring.cpp");
  fs::copy_file(kSource / "solution" / "spring.cpp", in / "doejane_1234_5099_spring-1.cpp");
  // smithjohn uploads one zip of the starter's files, late.
  std::vector<a6::test::staging::Entry> starter;
  for (const std::string& file : kTaskFiles) {
    starter.push_back({"a6/" + file, readAll(kSource / "starter" / file)});
  }
  ASSERT_EQ(a6::test::staging::writeArchive(in / "smithjohn_LATE_2345_6001_submission.zip", true,
                                            starter),
            "");
  // leeann uploads forces.cpp only.
  fs::copy_file(kSource / "solution" / "forces.cpp", in / "leeann_3456_7001_forces.cpp");
  writeAll(in / "grading_notes.txt", "from the TA");

  const Ran r = batchRun(in, dir / "out", "-j 2");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("canvas layout"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("grading_notes.txt"), std::string::npos) << "noted\n" << r.output;
  EXPECT_NE(r.output.find("submitted late"), std::string::npos) << r.output;
  const Gradebook g = readGradebook(dir / "out" / "gradebook.csv");
  ASSERT_EQ(g.error, "");
  ASSERT_EQ(g.rows.size(), 3u) << r.output;
  const auto* jane = g.row("doejane");
  ASSERT_NE(jane, nullptr);
  EXPECT_EQ(jane->at("sid"), "1234");
  EXPECT_EQ(jane->at("status"), "graded");
  EXPECT_DOUBLE_EQ(pointsOf(*jane, "total"),
                   pointsOf(*jane, "max") + pointsOf(*jane, "extra_credit"))
      << "the later spring-1.cpp replaced the first upload: " << describe(*jane);
  EXPECT_EQ(readAll(dir / "out" / "doejane" / "submission" / "spring.cpp"),
            readAll(kSource / "solution" / "spring.cpp"));
  const auto* john = g.row("smithjohn");
  ASSERT_NE(john, nullptr);
  EXPECT_EQ(john->at("status"), "graded") << "the zip's seven files were read: " << describe(*john);
  EXPECT_DOUBLE_EQ(pointsOf(*john, "total"), 0);
  const auto* ann = g.row("leeann");
  ASSERT_NE(ann, nullptr);
  EXPECT_EQ(ann->at("status"), "build failed") << "five files missing: " << describe(*ann);
  EXPECT_DOUBLE_EQ(pointsOf(*ann, "task2"), pointsOf(*jane, "task2")) << describe(*ann);
  EXPECT_DOUBLE_EQ(pointsOf(*ann, "task1"), 0) << describe(*ann);
}

// A submission's compiler and probe cannot read another submission of the batch (a6_batch
// hides the input and output folders from them). Outside the build tree, which is hidden anyway.
// One submission cannot set another's grade through what is compiled: one text whose object
// depends on where it is compiled (here, whether alice's results exist, which only alice's
// grading sees) gives each grading its own object, in any order and in a regrade.
TEST(Batch, TheSameTextCompiledInTwoGradingsGivesEachItsOwnObject) {
  if (geteuid() != 0) GTEST_SKIP() << "only root hides the other submissions' folders";
  const fs::path dir = caseDir("same_text");
  const fs::path in = dir / "in", out = dir / "out";
  const std::string probe = (out / "alice" / "results.json").string();
  const std::string forces = "#if __has_include(\"" + probe + "\")\n" +
                             readAll(kSource / "starter" / "forces.cpp") + "\n#else\n" +
                             readAll(kSource / "solution" / "forces.cpp") + "\n#endif\n";
  for (const char* student : {"alice", "bob"}) {
    fs::create_directories(in / student);
    fs::copy(kSource / "solution", in / student, fs::copy_options::recursive);
    writeAll(in / student / "forces.cpp", forces);
  }
  for (const std::string extra : {"-j 1", "-j 1 --force", "-j 2 --force"}) {
    const Ran r = batchRun(in, out, extra);
    EXPECT_EQ(r.status, 0) << r.output;
    const Gradebook g = readGradebook(out / "gradebook.csv");
    ASSERT_EQ(g.error, "") << r.output;
    const auto* alice = g.row("alice");
    const auto* bob = g.row("bob");
    ASSERT_TRUE(alice != nullptr && bob != nullptr) << r.output;
    EXPECT_DOUBLE_EQ(pointsOf(*alice, "task2"), 0) << extra << ": alice's compile saw her results";
    EXPECT_DOUBLE_EQ(pointsOf(*bob, "task2"), rubricPoints(false).at(2))
        << extra << ": bob was handed an object compiled for alice";
  }
}

TEST(Batch, ASubmissionCannotReadAnotherOne) {
  if (geteuid() != 0) GTEST_SKIP() << "only root hides folders (mount namespaces)";
  // Not in /tmp either: the probe's sandbox covers /tmp whatever a6_batch asks.
  char name[] = "/srv/a6_batch_test.XXXXXX";
  if (!fs::is_directory("/srv")) GTEST_SKIP() << "no /srv to grade a batch outside /tmp in";
  ASSERT_NE(mkdtemp(name), nullptr);
  const fs::path dir = name;
  fs::permissions(dir, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec |
                           fs::perms::group_read | fs::perms::others_read);
  const fs::path in = dir / "in", out = dir / "out";
  fs::create_directories(in);
  fs::copy(kSource / "solution", in / "alice", fs::copy_options::recursive);
  // mallory's spring.cpp compiles alice's when the compiler can see it, and tries to read it
  // before main, when the probe starts.
  const std::string alice = (in / "alice" / "spring.cpp").string();
  fs::copy(kSource / "solution", in / "mallory", fs::copy_options::recursive);
  writeAll(in / "mallory" / "spring.cpp",
           "#if __has_include(\"" + alice + "\")\n#include \"" + alice + "\"\n#else\n" +
               readAll(kSource / "starter" / "spring.cpp") +
               "\n#endif\n"
               "#include <cstdio>\n"
               "namespace {\n"
               "const bool peeked = [] {\n"
               "  std::FILE* f = std::fopen(\"" +
               alice +
               "\", \"r\");\n"
               "  std::printf(f != nullptr ? \"PEEKED at alice\\n\" : \"could not peek\\n\");\n"
               "  std::fflush(stdout);\n"
               "  if (f != nullptr) std::fclose(f);\n"
               "  return f != nullptr;\n"
               "}();\n"
               "}  // namespace\n");
  const Ran r = batchRun(in, out, "-j 2");
  EXPECT_EQ(r.status, 0) << r.output;
  const Gradebook g = readGradebook(out / "gradebook.csv");
  ASSERT_EQ(g.error, "");
  const auto* a = g.row("alice");
  const auto* m = g.row("mallory");
  ASSERT_TRUE(a != nullptr && m != nullptr) << r.output;
  EXPECT_GT(pointsOf(*a, "task1"), 0);
  EXPECT_DOUBLE_EQ(pointsOf(*m, "task1"), 0) << "the compiler saw alice's spring.cpp";
  const std::string report = readAll(out / "mallory" / "report.html");
  EXPECT_NE(report.find("could not peek"), std::string::npos) << "the probe's output is reported";
  EXPECT_EQ(report.find("PEEKED"), std::string::npos) << "the probe read alice's spring.cpp";
  fs::remove_all(dir);
}

}  // namespace
