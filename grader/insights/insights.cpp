// Reading results.json files and summing them over the class. See insights.h.
#include "insights/insights.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <system_error>

#include "batch/batch.h"  // parseGradescopeMetadata, gradescopeRoot
#include "common/read_all.h"

namespace a6::grader::insights {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// A results.json is a few hundred kB: anything larger is not read (a problem, not a grade).
constexpr std::size_t kLargestResults = 16u << 20;

SubmissionResult ungraded(const std::string& key, const std::string& problem) {
  SubmissionResult s;
  s.key = key;
  s.problem = problem;
  return s;
}

// Members read only when of their type: an export or a damaged file can hold anything.
std::string stringAt(const Json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}
// A finite number, else the fallback (1e999 parses to infinity).
double numberAt(const Json& j, const char* key, double fallback = 0) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return fallback;
  const double x = j[key].get<double>();
  return std::isfinite(x) ? x : fallback;
}
int countAt(const Json& j, const char* key) {
  return static_cast<int>(std::clamp(numberAt(j, key), 0.0, 1e9));
}
// The object at `key`, by reference (no copy of a deep tree), or an empty one.
const Json& objectAt(const Json& j, const char* key) {
  static const Json empty = Json::object();
  if (!j.is_object()) return empty;
  const auto it = j.find(key);
  return it != j.end() && it->is_object() ? *it : empty;
}

// "Task 4: cloth (12/14 checks)" -> "Task 4: cloth" (by hand: std::regex recurses per
// character, and a name is whatever the file holds).
std::string itemName(const std::string& shown) {
  if (shown.size() < 4 || shown.back() != ')') return shown;
  const std::size_t open = shown.rfind(" (");
  if (open == std::string::npos) return shown;
  const std::string inside = shown.substr(open + 2, shown.size() - open - 3);  // "12/14 checks"
  const std::size_t slash = inside.find('/'), space = inside.find(' ');
  const auto digits = [&](std::size_t from, std::size_t to) {
    return to > from && std::all_of(inside.begin() + static_cast<std::ptrdiff_t>(from),
                                    inside.begin() + static_cast<std::ptrdiff_t>(to),
                                    [](char c) { return c >= '0' && c <= '9'; });
  };
  const bool counts = slash != std::string::npos && space != std::string::npos && slash < space &&
                      digits(0, slash) && digits(slash + 1, space) &&
                      (inside.substr(space) == " checks" || inside.substr(space) == " check");
  return counts ? shown.substr(0, open) : shown;
}

ItemResult itemOf(const Json& t) {
  ItemResult item;
  item.name = itemName(stringAt(t, "name"));
  item.number = stringAt(t, "number");
  item.score = numberAt(t, "score");
  item.max = numberAt(t, "max_score");
  item.passed = stringAt(t, "status") == "passed";
  if (t.contains("tags") && t["tags"].is_array()) {
    for (const Json& tag : t["tags"]) {
      const std::string s = tag.is_string() ? tag.get<std::string>() : "";
      if (s == "extra_credit") item.extraCredit = true;
      if (const int task = courseTasks().ofTag(s); task > 0) item.task = task;
    }
  }
  const Json& extra = objectAt(t, "extra_data");
  item.mistake = stringAt(extra, "mistake");
  item.mistakeText = stringAt(extra, "mistake_text");
  if (const Json worth = extra.value("points", Json()); worth.is_number()) {
    const double points = worth.get<double>();
    if (std::isfinite(points) && points >= 0) item.worth = points;
  }
  if (extra.contains("checks") && extra["checks"].is_array()) {
    for (const Json& check : extra["checks"]) {
      if (item.checks.size() == kMostChecksOfAnItem) break;
      if (check.is_string()) item.checks.push_back(check.get<std::string>());
    }
  }
  return item;
}

// The task files that did not compile, from extra_data.build (file -> status).
std::string brokenFiles(const Json& build) {
  std::string files;
  for (const auto& [file, status] : build.items()) {
    if (status.is_string() && status.get<std::string>() == "compiled") continue;
    files += (files.empty() ? "" : ", ") + file;
  }
  return files;
}

void readExtra(const Json& extra, SubmissionResult& s) {
  for (const auto& [check, status] : objectAt(extra, "tests").items()) {
    s.checks[check] = status.is_string() && status.get<std::string>() == "passed";
  }
  const Json& incidents = objectAt(extra, "incidents");
  s.incidents.crashes = countAt(incidents, "crashes");
  s.incidents.timeouts = countAt(incidents, "timeouts");
  s.incidents.startFailures = countAt(incidents, "start_failures");
  s.build = brokenFiles(objectAt(extra, "build"));
  const auto diagnoses = extra.find("diagnoses");
  if (diagnoses == extra.end() || !diagnoses->is_array()) return;
  for (const Json& d : *diagnoses) {
    if (s.diagnoses.size() >= 16) break;  // one per task: more is not the grader's
    const std::string id = stringAt(d, "diagnosis");
    if (!id.empty())
      s.diagnoses.push_back(
          {id.substr(0, 120), stringAt(d, "text").substr(0, 2000), countAt(d, "task"), {}});
  }
}

// a6_batch's marker (batch.json) of a submission that has no results: why.
std::string markerProblem(const fs::path& marker) {
  const Json m = Json::parse(readAll(marker, kLargestResults), nullptr, false);
  const std::string status = stringAt(m, "status"), reason = stringAt(m, "reason");
  if (status.empty()) return "no results.json, and its batch.json cannot be read";
  return reason.empty() ? status : status + ": " + reason;
}

// The folder's results.json: a plain file (not a link) at its top only: a student can submit a
// file of that name anywhere below.
fs::path findResults(const fs::path& dir) {
  std::error_code ec;
  const fs::path file = dir / "results.json";
  return fs::is_regular_file(fs::symlink_status(file, ec)) ? file : fs::path();
}

std::string peopleOf(const std::vector<batch::Person>& people, const std::string& fallback) {
  std::string names;
  for (const batch::Person& p : people) names += (names.empty() ? "" : ", ") + p.name;
  return names.empty() ? fallback : names;
}

// The export's submission_<id>/ folders, each named by its submitters.
std::vector<std::pair<std::string, fs::path>> submissionsOf(const fs::path& root) {
  const auto people =
      batch::parseGradescopeMetadata(readAll(root / "submission_metadata.yml", kLargestResults));
  std::vector<std::pair<std::string, fs::path>> all;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(root, ec)) {
    const std::string name = e.path().filename().string();
    if (!e.is_directory(ec) || name.rfind("submission_", 0) != 0) continue;
    const auto who = people.find(name);
    all.emplace_back(
        peopleOf(who == people.end() ? std::vector<batch::Person>{} : who->second, name), e.path());
  }
  std::sort(all.begin(), all.end());
  return all;
}

std::vector<SubmissionResult> readGradescope(const fs::path& root,
                                             std::vector<std::string>& notes) {
  std::vector<SubmissionResult> all;
  int missing = 0;
  for (const auto& [key, folder] : submissionsOf(root)) {
    const fs::path results = findResults(folder);
    missing += results.empty();
    all.push_back(results.empty() ? ungraded(key, "no results.json in the export")
                                  : readResults(key, readAll(results, kLargestResults)));
  }
  if (missing > 0) {
    notes.push_back(std::to_string(missing) + " of " + std::to_string(all.size()) +
                    " exported submissions hold no results.json: regrade the export with a6_batch "
                    "for their results");
  }
  return all;
}

std::vector<SubmissionResult> readBatch(const fs::path& folder, std::vector<std::string>& notes) {
  std::vector<SubmissionResult> all;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    const std::string key = e.path().filename().string();
    if (!e.is_directory(ec) || key.empty() || key[0] == '.') continue;  // .similarity: work
    const fs::path results = e.path() / "results.json", marker = e.path() / "batch.json";
    if (fs::is_regular_file(results, ec)) {
      all.push_back(readResults(key, readAll(results, kLargestResults)));
      if (fs::is_regular_file(e.path() / "report.html", ec))
        all.back().report = key + "/report.html";
    } else if (fs::is_regular_file(marker, ec)) {
      all.push_back(ungraded(key, markerProblem(marker)));
    } else {
      notes.push_back(key + "/: no results.json or batch.json (not a graded submission)");
    }
  }
  return all;
}

}  // namespace

SubmissionResult readResults(const std::string& key, const std::string& resultsJson) {
  SubmissionResult s;
  s.key = key;
  const Json r = Json::parse(resultsJson, nullptr, false);
  if (r.is_discarded() || !r.is_object() || !r.contains("tests") || !r["tests"].is_array()) {
    s.problem =
        resultsJson.empty() ? "its results.json is empty" : "its results.json cannot be read";
    return s;
  }
  const Json& extra = objectAt(r, "extra_data");
  s.rubric = stringAt(extra, "rubric");
  if (extra.contains("errors") && extra["errors"].is_array() && !extra["errors"].empty()) {
    s.problem =
        "grader error: " + (extra["errors"][0].is_string() ? extra["errors"][0].get<std::string>()
                                                           : extra["errors"][0].dump());
    return s;
  }
  if (const std::string refused = stringAt(extra, "refused"); !refused.empty()) {
    s.problem = "not graded: " + refused;  // 0 points, as in the gradebook
    s.total = numberAt(r, "score");
    s.max = numberAt(extra, "max_score");
    return s;
  }
  double max = 0;
  for (const Json& t : r["tests"]) {
    if (!t.is_object()) continue;
    s.items.push_back(itemOf(t));
    max += s.items.back().max;
    if (s.items.back().extraCredit) s.extraCredit += s.items.back().score;
  }
  s.max = numberAt(extra, "max_score", max);
  if (r.contains("score") && r["score"].is_number() && std::isfinite(r["score"].get<double>()))
    s.total = r["score"].get<double>();
  if (!s.total) s.problem = "its results.json has no score";
  readExtra(extra, s);
  return s;
}

std::vector<std::pair<std::string, fs::path>> exportedSubmissions(const fs::path& folder) {
  const fs::path root = batch::gradescopeRoot(folder);
  return root.empty() ? std::vector<std::pair<std::string, fs::path>>{} : submissionsOf(root);
}

std::vector<SubmissionResult> readFolder(const fs::path& folder, std::vector<std::string>& notes) {
  const fs::path gradescope = batch::gradescopeRoot(folder);
  std::vector<SubmissionResult> all =
      gradescope.empty() ? readBatch(folder, notes) : readGradescope(gradescope, notes);
  std::sort(all.begin(), all.end(),
            [](const SubmissionResult& a, const SubmissionResult& b) { return a.key < b.key; });
  return all;
}

int taskOfCheck(const std::string& check, const TaskTable& tasks) { return tasks.ofCheck(check); }

namespace {

std::string itemKey(const ItemResult& item) { return item.number + "\t" + item.name; }

void addItems(const SubmissionResult& s, std::map<std::string, ItemStats>& items) {
  for (const ItemResult& item : s.items) {
    ItemStats& st = items[itemKey(item)];
    st.name = item.name;
    st.number = item.number;
    st.task = item.task;
    st.extraCredit = item.extraCredit;
    st.points = std::max(st.points, item.extraCredit ? item.score : item.max);
    ++st.graded;
    st.full += item.passed;
    st.mean += item.score;  // a sum until summarize() divides
  }
}

void addMistakes(const SubmissionResult& s, std::map<std::string, MistakeStats>& mistakes) {
  std::set<std::string> named;
  for (const ItemResult& item : s.items) {
    if (item.mistake.empty() || !named.insert(item.mistake).second) continue;
    MistakeStats& m = mistakes[item.mistake];
    m.id = item.mistake;
    m.task = item.task;
    if (m.example.empty()) m.example = item.mistakeText;
    m.who.push_back(s.key);
  }
}

// Each diagnosed part of a submission, counted once per submission.
void addDiagnoses(const SubmissionResult& s, std::map<std::string, MistakeStats>& parts) {
  std::set<std::string> seen;
  for (const MistakeStats& d : s.diagnoses) {
    if (!seen.insert(d.id).second) continue;
    MistakeStats& m = parts[d.id];
    m.id = d.id;
    m.task = d.task;
    if (m.example.empty()) m.example = d.example;
    m.who.push_back(s.key);
  }
}

// The stats of `byId` in a list, most often first.
std::vector<MistakeStats> mostOftenFirst(std::map<std::string, MistakeStats>& byId) {
  std::vector<MistakeStats> out;
  for (auto& [id, m] : byId) out.push_back(std::move(m));
  std::stable_sort(out.begin(), out.end(), [](const MistakeStats& a, const MistakeStats& b) {
    return a.who.size() > b.who.size();
  });
  return out;
}

// Points lost per item: what it is worth times the gradings, less what they got.
void finishItems(std::map<std::string, ItemStats>& items, ClassInsights& c) {
  for (auto& [key, st] : items) {
    st.lost = st.points * st.graded - st.mean;
    st.mean = st.graded == 0 ? 0 : st.mean / st.graded;
    c.items.push_back(st);
  }
  std::sort(c.items.begin(), c.items.end(), [](const ItemStats& a, const ItemStats& b) {
    return a.number != b.number ? a.number < b.number : a.name < b.name;
  });
}

// What each check cost: a grading's points lost on an item (its worth, or else the most the
// class got, less its score), shared evenly among the item's checks it ran and failed.
void costChecks(const SubmissionResult& s, const std::map<std::string, ItemStats>& items,
                std::map<std::string, CheckStats>& checks) {
  for (const ItemResult& item : s.items) {
    std::set<std::string> named, failed;
    for (const std::string& name : item.checks) {
      const auto ran = s.checks.find(name);
      if (ran == s.checks.end() || !named.insert(name).second) continue;
      ++checks[name].costedRuns;
      if (!ran->second) failed.insert(name);
    }
    const double worth = item.worth.value_or(items.at(itemKey(item)).points);
    const double lost = std::max(0.0, worth - item.score);
    for (const std::string& name : failed) checks[name].lost += lost / double(failed.size());
  }
}

void flagChecks(ClassInsights& c) {
  if (c.graded < kFlagMinimum) return;
  for (const CheckStats& check : c.checks) {
    if (check.ran < kFlagMinimum) continue;
    if (check.passRate() <= kNearlyAllFail) c.flags.push_back({check.name, true});
    if (check.passed == check.ran) c.flags.push_back({check.name, false});
  }
}

}  // namespace

ClassInsights summarize(std::vector<SubmissionResult> submissions) {
  ClassInsights c;
  std::sort(submissions.begin(), submissions.end(),
            [](const SubmissionResult& a, const SubmissionResult& b) { return a.key < b.key; });
  std::map<std::string, ItemStats> items;
  std::map<std::string, CheckStats> checks;
  std::map<std::string, MistakeStats> mistakes, parts;
  for (const SubmissionResult& s : submissions) {
    if (!s.total) continue;
    ++c.graded;
    addItems(s, items);
    addMistakes(s, mistakes);
    addDiagnoses(s, parts);
    for (const auto& [name, passed] : s.checks) {
      CheckStats& st = checks[name];
      st.name = name;
      st.task = taskOfCheck(name);
      ++st.ran;
      st.passed += passed;
    }
  }
  finishItems(items, c);
  for (const SubmissionResult& s : submissions) {
    if (s.total) costChecks(s, items, checks);
  }
  for (auto& [name, st] : checks) c.checks.push_back(st);
  c.mistakes = mostOftenFirst(mistakes);
  c.parts = mostOftenFirst(parts);
  flagChecks(c);
  c.submissions = std::move(submissions);
  return c;
}

}  // namespace a6::grader::insights
