#include "report/report.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>

#include "common/fixed.h"
#include "harness/tasks.h"
#include "render/replay.h"
#include "report/replay_html.h"

namespace a6::assets {  // the page's assets, embedded at build time (a6_embedded_text)
extern const char report_css[];
}  // namespace a6::assets

namespace a6::grader {

namespace {

using Json = nlohmann::ordered_json;

constexpr std::size_t kItemOutputCap = 24u << 10;  // per rubric item in results.json
constexpr std::size_t kMessageCap = 8u << 10;      // per test message
constexpr std::size_t kCompilerCap = 8u << 10;     // compiler messages per task
constexpr std::uintmax_t kImageCap = 16u << 20;    // an image larger than this is not embedded

std::string fmt(double x) { return formatPoints(x); }

// The task of a task file's name, 0 otherwise.
int taskOf(const std::string& file) { return courseTasks().ofFile(file); }

const TaskBuild* buildOf(const GradeReport& report, int task) {
  for (const TaskBuild& t : report.build.tasks) {
    if (task > 0 && taskOf(t.file) == task) return &t;
  }
  return nullptr;
}

// How a task file built: a keyword (results.json's extra_data.build) and a sentence (the output,
// the report and the terminal).
struct BuildWords {
  const char* keyword;
  const char* sentence;
};

BuildWords buildWords(const TaskBuild& t) {
  switch (t.status) {
    case TaskBuild::Status::Compiled:
      return {"compiled", "compiled"};
    case TaskBuild::Status::Missing:
      return {"missing", "missing from the submission: graded with the starter code"};
    case TaskBuild::Status::CompileError:
      return {"did not compile", "did not compile: graded with the starter code"};
    case TaskBuild::Status::TimedOut:
      return {"compiler timed out", "the compiler ran out of time: graded with the starter code"};
    case TaskBuild::Status::LinkError:
      return {"did not link or start",
              "compiled, but could not be linked or started with the framework: graded with the "
              "starter code"};
  }
  return {"?", "?"};
}

std::string itemTitle(const ScoredItem& s) {
  const int total = s.passed + s.failed;
  return s.item.name + " (" + std::to_string(s.passed) + "/" + std::to_string(total) +
         (total == 1 ? " check)" : " checks)");
}

// The note for an item whose passed checks agree only to float precision (tasks 1-5: Box2D's
// task 6 is float by design), or "". It costs nothing.
std::string precisionNote(const ScoredItem& s) {
  if (s.item.task < 1 || s.item.task > 5) return "";
  double agreement = 0;
  for (const TestOutcome* t : s.tests) {
    if (t->passed) agreement = std::max(agreement, t->agreement);
  }
  if (!(agreement > 0)) return "";
  char about[32];
  std::snprintf(about, sizeof about, "1e%d", static_cast<int>(std::lround(std::log10(agreement))));
  return std::string("Note: your values agree with the reference to about ") + about +
         ", relative: that is float rounding; the framework uses double. It costs nothing.\n";
}

// The known mistake a failed item's task matched (grader/mistakes/), or null.
const NamedMistake* mistakeOf(const GradeReport& report, const ScoredItem& s) {
  if (s.failed == 0) return nullptr;
  for (const NamedMistake& m : report.mistakes) {
    if (m.task == s.item.task) return &m;
  }
  return nullptr;
}

// The first failed check's hint ("  hint: ..." in its message), or "".
std::string firstHint(const ScoredItem& s) {
  for (const TestOutcome* t : s.tests) {
    const std::size_t at = t->passed ? std::string::npos : t->message.find("hint: ");
    if (at == std::string::npos) continue;
    const std::size_t end = t->message.find('\n', at);
    return "Hint: " + t->message.substr(at + 6, end == std::string::npos ? end : end - at - 6);
  }
  return "";
}

// The first divergences of an item's failed checks (checks/divergence.h), in its checks' order.
std::vector<const Divergence*> divergencesOf(const GradeReport& report, const ScoredItem& s) {
  std::vector<const Divergence*> out;
  for (const TestOutcome* t : s.tests) {
    for (const Divergence& d : report.divergences) {
      if (!t->passed && d.check == t->name) out.push_back(&d);
    }
  }
  return out;
}

// A failed check's message as the item shows it: where the task has a named mistake or a
// measurement (mistakeOf), without the check's own hint lines, which guess from which check
// failed and may blame a part that measured right (mistakes/measure.h).
std::string shownMessage(const GradeReport& report, const ScoredItem& s, const TestOutcome& t) {
  if (mistakeOf(report, s) == nullptr) return t.message;
  std::istringstream in(t.message);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    if (line.find("hint: ") == std::string::npos) out += line + "\n";
  }
  if (!out.empty() && (t.message.empty() || t.message.back() != '\n')) out.pop_back();
  return out;
}

// The text Gradescope shows under an item: the known mistake or the measurement, or else the
// first hint; why the task used the starter; each failing test with its message; the precision
// note.
std::string itemOutput(const GradeReport& report, const ScoredItem& s) {
  std::string out;
  if (const NamedMistake* m = mistakeOf(report, s)) {
    out += m->text + "\n\n";
  } else if (const std::string hint = firstHint(s); !hint.empty()) {
    out += hint + "\n\n";
  }
  const std::vector<const Divergence*> divergences = divergencesOf(report, s);
  for (const Divergence* d : divergences) out += d->check + ": " + d->text + "\n";
  if (!divergences.empty()) out += "\n";
  if (const TaskBuild* t = buildOf(report, s.item.task); t != nullptr && t->usesStarter()) {
    out += t->file + " " + buildWords(*t).sentence + ".\n";
    if (!t->messages.empty())
      out += "Compiler messages:\n" + cap(t->messages, kCompilerCap, "") + "\n";
    out += "\n";
  }
  if (s.tests.empty()) {
    out += "No check matched this item (a rubric problem; your instructor has been told).\n";
  } else if (s.failed == 0) {
    out += s.passed == 1 ? "The check passed.\n"
                         : "All " + std::to_string(s.passed) + " checks passed.\n";
  } else {
    out += std::to_string(s.failed) + " of " + std::to_string(s.tests.size()) +
           (s.tests.size() == 1 ? " check failed" : " checks failed") +
           (s.item.allOrNothing ? " (all-or-nothing: no points)" : "") + ":\n";
    for (const TestOutcome* t : s.tests) {
      if (t->passed) continue;
      out +=
          "\nFAILED " + t->name + "\n" + cap(shownMessage(report, s, *t), kMessageCap, "") + "\n";
    }
  }
  out += precisionNote(s);
  return cap(out, kItemOutputCap, "");
}

// The score line a student may see now: only the visible items count, and it says so when
// others exist (their outcome must not show through the total before the due date).
std::string visibleScoreLine(const GradeReport& report) {
  const VisibleTotals v = visibleTotals(report);
  std::string line = (v.laterItems == 0 ? "Score: " : "Score on the items shown now: ") +
                     fmt(v.score) + " / " + fmt(v.max);
  if (v.extraCredit > 0) line += " (+" + fmt(v.extraCredit) + " extra credit)";
  if (v.laterItems > 0) {
    line += "\nNot counted here: " + std::to_string(v.laterItems) +
            (v.laterItems == 1 ? " item" : " items") + " worth " + fmt(v.laterPoints) + " points" +
            (v.laterExtraCredit > 0 ? " (+" + fmt(v.laterExtraCredit) + " extra credit)" : "") +
            ", shown to you later (after the due date, or when the grades are published)";
  }
  return line + "\n";
}

std::string overallOutput(const GradeReport& report) {
  std::ostringstream out;
  if (!report.rubricTitle.empty()) out << report.rubricTitle << "\n";
  if (!report.refused.empty()) {
    out << "Score: 0" << (report.maxScore > 0 ? " / " + fmt(report.maxScore) : "")
        << "\nNot graded: " << report.refused << "\n";
    for (const std::string& note : report.intake.notes) out << "Note: " << note << "\n";
    return out.str();
  }
  out << visibleScoreLine(report);
  out << "Seed of the randomised checks: " << report.seed << "\n";
  // What was taken from the submission.
  if (!report.intake.ok()) {
    out << "Your submission could not be read: " << report.intake.error << "\n";
  } else {
    std::string taken, missing;
    for (const std::string& f : kTaskFiles) {
      std::string& list = report.intake.files.count(f) != 0 ? taken : missing;
      list += (list.empty() ? "" : ", ") + f;
    }
    out << "Files taken from your submission: " << (taken.empty() ? "none" : taken) << "\n";
    if (!missing.empty()) out << "Not found (the starter code was used): " << missing << "\n";
    for (const std::string& note : report.intake.notes) out << "Note: " << note << "\n";
  }
  // Build status per task.
  if (!report.build.tasks.empty()) {
    out << "Build:\n";
    for (const TaskBuild& t : report.build.tasks) {
      out << "  Task " << taskOf(t.file) << " " << t.file << ": " << buildWords(t).sentence << "\n";
    }
  }
  if (!report.build.error.empty()) out << "Build failed: " << report.build.error << "\n";
  for (const std::string& e : report.errors) out << "Grader error: " << e << "\n";
  return out.str();
}

std::string readFile(const std::filesystem::path& file, std::uintmax_t limit, std::string& error) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) {
    error = "cannot read " + file.string() + ": " + ec.message();
    return {};
  }
  if (size > limit) {
    error = file.string() + " is too large to embed (" + std::to_string(size) + " bytes)";
    return {};
  }
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in && !in.eof()) error = "cannot read " + file.string();
  return bytes.str();
}

std::string mimeOf(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".ppm" || ext == ".pnm") return "image/x-portable-pixmap";
  if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
  return "image/png";
}

// results.json ---------------------------------------------------------------------------------

// One rubric item as a Gradescope test.
Json itemJson(const GradeReport& report, const ScoredItem& s) {
  Json t;
  t["name"] = itemTitle(s);
  t["number"] = s.number;
  t["score"] = s.score;
  // Extra credit carries its points in score over a max_score of 0, so the total can pass 100.
  t["max_score"] = s.item.extraCredit ? 0.0 : s.item.points;
  t["status"] = (s.failed == 0 && !s.tests.empty()) ? "passed" : "failed";
  t["visibility"] = toString(s.item.visibility);
  t["output"] = itemOutput(report, s);
  Json tags = Json::array();
  if (courseTasks().find(s.item.task) != nullptr) tags.push_back(courseTasks().tag(s.item.task));
  if (s.item.extraCredit) tags.push_back("extra_credit");
  if (s.item.allOrNothing) tags.push_back("all_or_nothing");
  t["tags"] = tags;
  // For a6_insights: what each check cost (the item's worth, extra credit too, and its checks).
  Json extra = {{"points", s.item.points}, {"checks", Json::array()}};
  for (const TestOutcome* test : s.tests) extra["checks"].push_back(test->name);
  if (const NamedMistake* m = mistakeOf(report, s)) {
    extra["mistake"] = m->id;
    extra["mistake_text"] = m->text;
  }
  t["extra_data"] = std::move(extra);
  return t;
}

// For instructors and scripts (never shown to students).
Json extraData(const GradeReport& report) {
  Json extra;
  extra["seed"] = std::to_string(report.seed);
  extra["submission"] = report.submission;
  extra["rubric"] = report.rubricTitle;
  extra["max_score"] = report.maxScore;
  extra["extra_credit"] = report.extraCredit;
  extra["seconds"] = roundPoints(report.seconds);
  extra["seconds_by_stage"] = {{"build", roundPoints(report.buildSeconds)},
                               {"checks", roundPoints(report.checksSeconds)}};
  extra["grader_peak_rss_mib"] = roundPoints(report.peakRssMiB);
  Json outcomes = Json::object();
  for (const TestOutcome& t : report.tests) outcomes[t.name] = t.passed ? "passed" : "failed";
  extra["tests"] = std::move(outcomes);
  // The output's "Build:" lines as keywords, for scripts (a6_batch's "build failed").
  Json build = Json::object();
  for (const TaskBuild& t : report.build.tasks) build[t.file] = buildWords(t).keyword;
  extra["build"] = std::move(build);
  Json mistakes = Json::array();
  for (const NamedMistake& m : report.mistakes) {
    mistakes.push_back({{"task", m.task},
                        {"mistake", m.id},
                        {"evidence", m.evidence},
                        {"measured_only", m.measuredOnly}});
  }
  extra["mistakes"] = std::move(mistakes);
  Json diagnoses = Json::array();
  for (const NamedMistake& m : report.diagnoses) {
    diagnoses.push_back({{"task", m.task},
                         {"diagnosis", m.id},
                         {"text", m.text},
                         {"measured_only", m.measuredOnly}});
  }
  extra["diagnoses"] = std::move(diagnoses);
  Json divergences = Json::array();
  for (const Divergence& d : report.divergences) {
    divergences.push_back(
        {{"check", d.check}, {"step", d.step}, {"steps", d.steps}, {"quantity", d.quantity}});
  }
  extra["divergences"] = std::move(divergences);
  extra["warnings"] = report.warnings;
  extra["notes"] = report.notes;
  extra["errors"] = report.errors;
  if (!report.refused.empty()) extra["refused"] = report.refused;
  extra["incidents"] = {{"crashes", report.incidents.crashes},
                        {"timeouts", report.incidents.timeouts},
                        {"start_failures", report.incidents.startFailures}};
  return extra;
}

}  // namespace

std::string resultsJson(const GradeReport& report) {
  Json root;
  root["score"] = report.score;
  root["execution_time"] = static_cast<long long>(std::ceil(std::max(0.0, report.seconds)));
  root["output"] = htmlEscape(overallOutput(report));
  root["output_format"] = "simple_format";
  root["test_output_format"] = "text";
  root["test_name_format"] = "text";
  root["visibility"] = "visible";
  root["stdout_visibility"] = "hidden";
  Json tests = Json::array();
  for (const ScoredItem& s : report.items) tests.push_back(itemJson(report, s));
  root["tests"] = std::move(tests);
  root["extra_data"] = extraData(report);
  // Student-derived text may not be valid UTF-8: replace bad bytes rather than throw.
  return root.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

void score(GradeReport& report, const Rubric& rubric) {
  Scores s = scoreTests(report.tests, rubric);
  report.items = std::move(s.items);
  report.score = s.score;
  report.maxScore = s.maxScore;
  report.extraCredit = s.extraCredit;
  report.rubricTitle = std::move(s.rubricTitle);
  report.warnings.insert(report.warnings.end(), s.warnings.begin(), s.warnings.end());
}

std::string writeResultsJson(const GradeReport& report, const std::filesystem::path& file) {
  std::string text;
  try {
    text = resultsJson(report);
  } catch (const std::exception& e) {
    // Never leave Gradescope without a results.json: a minimal one that says what happened.
    Json fallback;
    fallback["score"] = 0;
    fallback["output"] =
        htmlEscape(std::string("The grader failed to write its report: ") + e.what());
    fallback["output_format"] = "simple_format";
    fallback["stdout_visibility"] = "hidden";
    fallback["tests"] = Json::array();
    text = fallback.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
  }
  return writeFileAtomically(file, text);
}

// HTML -----------------------------------------------------------------------------------------

std::string base64(const std::string& bytes) {
  return replay::toBase64(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

namespace {

const char* const kCss = a6::assets::report_css;  // grader/report/assets/report.css (embedded)

void htmlImages(std::ostringstream& out, const TestOutcome& t) {
  if (t.images.empty()) return;
  static const char* const captions[] = {"student", "reference", "difference"};
  out << "<div class=\"images\">";
  for (std::size_t i = 0; i < t.images.size(); ++i) {
    const std::string caption = i < 3 ? captions[i] : "image " + std::to_string(i + 1);
    std::string error;
    const std::string bytes = readFile(t.images[i], kImageCap, error);
    out << "<figure>";
    if (error.empty()) {
      out << "<img alt=\"" << caption << "\" src=\"data:" << mimeOf(t.images[i]) << ";base64,"
          << base64(bytes) << "\">";
    } else {
      out << "<pre>" << htmlEscape(error) << "</pre>";
    }
    out << "<figcaption>" << caption << ": " << htmlEscape(t.images[i].filename().string())
        << "</figcaption></figure>";
  }
  out << "</div>";
}

// A box of one kind ("error", "warn") with a title and a list, unless the list is empty.
void htmlBox(std::ostringstream& out, const char* kind, const char* title,
             const std::vector<std::string>& lines) {
  if (lines.empty()) return;
  out << "<div class=\"box " << kind << "\"><b>" << title << "</b><ul>";
  for (const std::string& line : lines) out << "<li>" << htmlEscape(line) << "</li>";
  out << "</ul></div>\n";
}

// The page's head, title, the score line and the boxes of what went wrong or is worth knowing.
void htmlHead(std::ostringstream& out, const GradeReport& report) {
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      << "<title>Grade report: " << htmlEscape(report.submission) << "</title>"
      << "<style>" << kCss << "</style></head><body>\n";
  out << "<h1>" << htmlEscape(report.rubricTitle.empty() ? "Grade report" : report.rubricTitle)
      << "</h1>\n";
  out << "<p>Submission <code>" << htmlEscape(report.submission) << "</code> &middot; score <b>"
      << fmt(report.score - report.extraCredit) << " / " << fmt(report.maxScore) << "</b>";
  if (report.extraCredit > 0) out << " (+" << fmt(report.extraCredit) << " extra credit)";
  out << " &middot; seed " << report.seed << " &middot; " << fixed(report.seconds, 2) << " s</p>\n";
  if (!report.refused.empty()) {
    out << "<div class=\"box error\"><b>Not graded</b><p>" << htmlEscape(report.refused)
        << "</p></div>\n";
  }
  // The intake's error shows here too, unless it is the only problem and said above.
  std::vector<std::string> problems;
  if (!report.intake.ok()) problems.push_back("intake: " + report.intake.error);
  if (!report.build.error.empty()) problems.push_back("build: " + report.build.error);
  problems.insert(problems.end(), report.errors.begin(), report.errors.end());
  const bool saidAbove = !report.intake.ok() && report.refused == report.intake.error;
  if (problems.size() > (saidAbove ? 1u : 0u)) htmlBox(out, "error", "Grading problems", problems);
  htmlBox(out, "warn", "Rubric warnings", report.warnings);
  htmlBox(out, "warn", "Notes on this run", report.notes);
}

void htmlScoreTable(std::ostringstream& out, const GradeReport& report) {
  out << "<h2>Score</h2>\n<table><tr><th>#</th><th>item</th><th>visibility</th>"
      << "<th class=\"num\">points</th><th class=\"num\">checks passed</th></tr>\n";
  for (const ScoredItem& s : report.items) {
    out << "<tr><td>" << s.number << "</td><td><a href=\"#item-" << s.number << "\">"
        << htmlEscape(s.item.name) << "</a>";
    if (s.item.extraCredit) out << "<span class=\"tag\">extra credit</span>";
    if (s.item.allOrNothing) out << "<span class=\"tag\">all or nothing</span>";
    out << "</td><td>" << toString(s.item.visibility) << "</td><td class=\"num\">" << fmt(s.score)
        << " / " << fmt(s.item.points) << "</td><td class=\"num "
        << (s.failed == 0 && !s.tests.empty() ? "pass" : "fail") << "\">" << s.passed << " / "
        << s.tests.size() << "</td></tr>\n";
  }
  out << "<tr><th></th><th>total</th><th></th><th class=\"num\">"
      << fmt(report.score - report.extraCredit) << " / " << fmt(report.maxScore);
  if (report.extraCredit > 0) out << " + " << fmt(report.extraCredit);
  out << "</th><th></th></tr></table>\n";
}

// The submission: each task file's graded copy and build, the intake's notes, the compiler's
// messages (open where a task uses the starter's stub).
void htmlSubmission(std::ostringstream& out, const GradeReport& report) {
  if (report.linked) {
    out << "<h2>Submission</h2>\n<p>The task files were compiled into the grading program "
        << "itself (a test's in-process grading): no copy, no sandboxed build.</p>\n";
    return;
  }
  out << "<h2>Submission</h2>\n<table><tr><th>task file</th><th>graded copy</th>"
      << "<th>build</th></tr>\n";
  for (std::size_t i = 0; i < kTaskFiles.size(); ++i) {
    const std::string& f = kTaskFiles[i];
    const auto found = report.intake.files.find(f);
    const TaskBuild* t = buildOf(report, static_cast<int>(i + 1));
    out << "<tr><td>Task " << i + 1 << " <code>" << f << "</code></td><td>"
        << (found != report.intake.files.end()
                ? "<code>" + htmlEscape(found->second.string()) + "</code>"
                : std::string("<span class=\"fail\">not found</span>"))
        << "</td><td>"
        << (t == nullptr ? std::string("not built")
                         : "<span class=\"" + std::string(t->usesStarter() ? "fail" : "pass") +
                               "\">" + htmlEscape(buildWords(*t).sentence) + "</span>")
        << "</td></tr>\n";
  }
  out << "</table>\n";
  if (!report.intake.notes.empty()) {
    out << "<p>Intake notes:</p><ul>";
    for (const std::string& n : report.intake.notes) out << "<li>" << htmlEscape(n) << "</li>";
    out << "</ul>\n";
  }
  for (const TaskBuild& t : report.build.tasks) {
    if (t.messages.empty()) continue;
    out << "<details" << (t.usesStarter() ? " open" : "")
        << "><summary>Compiler messages for <code>" << htmlEscape(t.file)
        << "</code></summary><pre>" << htmlEscape(cap(t.messages, 64u << 10, ""))
        << "</pre></details>\n";
  }
}

// One item with its tests: what each said when it failed, its images, its time.
void htmlItem(std::ostringstream& out, const GradeReport& report, const ScoredItem& s) {
  out << "<h2 id=\"item-" << s.number << "\">" << s.number << " " << htmlEscape(s.item.name)
      << " &mdash; " << fmt(s.score) << " / " << fmt(s.item.points) << "</h2>\n";
  if (const NamedMistake* m = mistakeOf(report, s)) {
    out << "<p class=\"mistake\"><strong>"
        << (m->measuredOnly ? "What the grader measured:" : "The mistake, named:") << "</strong> "
        << htmlEscape(m->text) << "</p>\n";
  }
  if (const std::vector<const Divergence*> ds = divergencesOf(report, s); !ds.empty()) {
    out << "<p class=\"divergence\"><strong>First divergence</strong> (each failed step "
           "check restarted from the physics' state before every step):</p>\n<ul>";
    for (const Divergence* d : ds)
      out << "<li><code>" << htmlEscape(d->check) << "</code>: " << htmlEscape(d->text) << "</li>";
    out << "</ul>\n";
  }
  if (s.tests.empty()) {
    out << "<p class=\"fail\">No test matched this item.</p>\n";
    return;
  }
  out << "<table><tr><th>test</th><th>result</th><th class=\"num\">time (s)</th></tr>\n";
  for (const TestOutcome* t : s.tests) {
    out << "<tr><td><code>" << htmlEscape(t->name) << "</code>";
    if (!t->passed && !t->message.empty()) {
      out << "<pre>" << htmlEscape(cap(shownMessage(report, s, *t), 32u << 10, "")) << "</pre>";
    }
    htmlImages(out, *t);
    out << "</td><td class=\"" << (t->passed ? "pass\">passed" : "fail\">failed")
        << "</td><td class=\"num\">" << fixed(t->seconds, 2) << "</td></tr>\n";
  }
  out << "</table>\n";
  if (const std::string note = precisionNote(s); !note.empty()) {
    out << "<p class=\"note\">" << htmlEscape(note) << "</p>\n";
  }
}

}  // namespace

std::string htmlReport(const GradeReport& report) {
  std::ostringstream out;
  htmlHead(out, report);
  htmlScoreTable(out, report);
  htmlSubmission(out, report);
  for (const ScoredItem& s : report.items) htmlItem(out, report, s);
  htmlReplays(out, report.replays);
  if (!report.probeOutput.empty()) {
    out << "<h2>Probe output</h2>\n<details><summary>What the student's code printed "
        << "(capped; never used for scoring)</summary><pre>" << htmlEscape(report.probeOutput)
        << "</pre></details>\n";
  }
  out << "</body></html>\n";
  return out.str();
}

std::string writeHtml(const GradeReport& report, const std::filesystem::path& file) {
  try {
    return writeFileAtomically(file, htmlReport(report));
  } catch (const std::exception& e) {
    return std::string("cannot write the HTML report: ") + e.what();
  }
}

// Terminal -------------------------------------------------------------------------------------

std::string terminalSummary(const GradeReport& report, bool color) {
  const char* green = color ? "\033[32m" : "";
  const char* red = color ? "\033[31m" : "";
  const char* bold = color ? "\033[1m" : "";
  const char* reset = color ? "\033[0m" : "";
  std::ostringstream out;
  out << bold << (report.rubricTitle.empty() ? "Grade" : report.rubricTitle) << reset << " — "
      << report.submission << " (seed " << report.seed << ")\n";
  out << "  " << std::left << std::setw(6) << "#" << std::setw(46) << "item" << std::right
      << std::setw(16) << "points"
      << "   checks\n";
  for (const ScoredItem& s : report.items) {
    std::string name = s.item.name + (s.item.extraCredit ? " [extra]" : "");
    if (name.size() > 45) name = name.substr(0, 42) + "...";
    const std::string points = fixed(s.score, 2) + " / " + fixed(s.item.points, 2);
    out << "  " << std::left << std::setw(6) << s.number << std::setw(46) << name << std::right
        << std::setw(16) << points << "   " << (s.failed == 0 && !s.tests.empty() ? green : red)
        << s.passed << " passed, " << s.failed << " failed" << reset << "\n";
  }
  auto totalLine = [&](const char* label, double score, double max, double extraCredit) {
    out << "  " << std::left << std::setw(52) << label << std::right << std::setw(16)
        << (fixed(score, 2) + " / " + fixed(max, 2));
    if (extraCredit > 0) out << "   +" << fixed(extraCredit, 2) << " extra credit";
    out << "\n";
  };
  totalLine("total", report.score - report.extraCredit, report.maxScore, report.extraCredit);
  if (const VisibleTotals v = visibleTotals(report); v.laterItems > 0) {
    totalLine("shown to students before the due date", v.score, v.max, v.extraCredit);
  }
  for (const TaskBuild& t : report.build.tasks) {
    if (t.usesStarter())
      out << "  " << red << t.file << ": " << buildWords(t).sentence << reset << "\n";
  }
  for (const NamedMistake& m : report.mistakes) {
    out << "  " << red << "task " << m.task << ": " << m.text << reset << "\n";
  }
  for (const std::string& w : report.warnings) out << "  warning: " << w << "\n";
  for (const std::string& n : report.notes) out << "  note: " << n << "\n";
  for (const std::string& e : report.errors) out << "  " << red << "error: " << e << reset << "\n";
  return out.str();
}

}  // namespace a6::grader
