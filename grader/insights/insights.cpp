// Reading results.json files and summing them over the class. See insights.h.
#include "insights/insights.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <system_error>

#include "batch/batch.h"  // parseGradescopeMetadata

namespace a6::grader::insights {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

SubmissionResult ungraded(const std::string& key, const std::string& problem) {
  SubmissionResult s;
  s.key = key;
  s.problem = problem;
  return s;
}

// The member `key` of `j` when it has that type, else the fallback: results.json is the
// grader's, but a Gradescope export or a damaged file can hold anything.
std::string stringAt(const Json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}
double numberAt(const Json& j, const char* key, double fallback = 0) {
  return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}
Json objectAt(const Json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_object() ? j[key] : Json::object();
}

// "Task 4: cloth (12/14 checks)" -> "Task 4: cloth".
std::string itemName(const std::string& shown) {
  static const std::regex counts(R"( \(\d+/\d+ checks?\)$)");
  return std::regex_replace(shown, counts, "");
}

ItemResult itemOf(const Json& t) {
  ItemResult item;
  item.name = itemName(stringAt(t, "name"));
  item.number = stringAt(t, "number");
  item.score = numberAt(t, "score");
  item.max = numberAt(t, "max_score");
  item.visibility = stringAt(t, "visibility");
  item.passed = stringAt(t, "status") == "passed";
  if (t.contains("tags") && t["tags"].is_array()) {
    for (const Json& tag : t["tags"]) {
      const std::string s = tag.is_string() ? tag.get<std::string>() : "";
      if (s == "extra_credit") item.extraCredit = true;
      if (s.size() == 5 && s.rfind("task", 0) == 0 &&
          std::isdigit(static_cast<unsigned char>(s[4])))
        item.task = s[4] - '0';
    }
  }
  const Json extra = objectAt(t, "extra_data");
  item.mistake = stringAt(extra, "mistake");
  item.mistakeText = stringAt(extra, "mistake_text");
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
  const Json checks = objectAt(extra, "tests");  // kept: items() refers into it
  for (const auto& [check, status] : checks.items()) {
    s.checks[check] = status.is_string() && status.get<std::string>() == "passed";
  }
  const Json incidents = objectAt(extra, "incidents");
  s.incidents.crashes = static_cast<int>(numberAt(incidents, "crashes"));
  s.incidents.timeouts = static_cast<int>(numberAt(incidents, "timeouts"));
  s.incidents.startFailures = static_cast<int>(numberAt(incidents, "start_failures"));
  s.build = brokenFiles(objectAt(extra, "build"));
}

// a6_batch's marker (batch.json) of a submission that has no results: why.
std::string markerProblem(const fs::path& marker) {
  const Json m = Json::parse(readAll(marker), nullptr, false);
  const std::string status = stringAt(m, "status"), reason = stringAt(m, "reason");
  if (status.empty()) return "no results.json, and its batch.json cannot be read";
  return reason.empty() ? status : status + ": " + reason;
}

// The first results.json in `dir` or below it (a Gradescope export's layout depends on its
// date), in name order; "" when none.
fs::path findResults(const fs::path& dir) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it.depth() > 3) it.disable_recursion_pending();
    if (it->path().filename() == "results.json" && it->is_regular_file(ec))
      found.push_back(it->path());
  }
  std::sort(found.begin(), found.end());
  return found.empty() ? fs::path() : found.front();
}

// The folder holding a Gradescope export's submission_metadata.yml: `folder` or its only
// sub-folder; empty when neither.
fs::path gradescopeRoot(const fs::path& folder) {
  std::error_code ec;
  if (fs::is_regular_file(folder / "submission_metadata.yml", ec)) return folder;
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    if (e.is_directory(ec)) dirs.push_back(e.path());
  }
  if (dirs.size() == 1 && fs::is_regular_file(dirs[0] / "submission_metadata.yml", ec))
    return dirs[0];
  return {};
}

std::string peopleOf(const std::vector<batch::Person>& people, const std::string& fallback) {
  std::string names;
  for (const batch::Person& p : people) names += (names.empty() ? "" : ", ") + p.name;
  return names.empty() ? fallback : names;
}

// The export's submission_<id>/ folders, each named by its submitters.
std::vector<std::pair<std::string, fs::path>> submissionsOf(const fs::path& root) {
  const auto people = batch::parseGradescopeMetadata(readAll(root / "submission_metadata.yml"));
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
                                  : readResults(key, readAll(results)));
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
      all.push_back(readResults(key, readAll(results)));
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
  const Json extra = objectAt(r, "extra_data");
  s.rubric = stringAt(extra, "rubric");
  if (extra.contains("errors") && extra["errors"].is_array() && !extra["errors"].empty()) {
    s.problem =
        "grader error: " + (extra["errors"][0].is_string() ? extra["errors"][0].get<std::string>()
                                                           : extra["errors"][0].dump());
    return s;
  }
  if (const std::string refused = stringAt(extra, "refused"); !refused.empty()) {
    s.problem = "not graded: " + refused;
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
  if (r.contains("score") && r["score"].is_number()) s.total = r["score"].get<double>();
  if (!s.total) s.problem = "its results.json has no score";
  readExtra(extra, s);
  return s;
}

std::vector<std::pair<std::string, fs::path>> exportedSubmissions(const fs::path& folder) {
  const fs::path root = gradescopeRoot(folder);
  return root.empty() ? std::vector<std::pair<std::string, fs::path>>{} : submissionsOf(root);
}

std::vector<SubmissionResult> readFolder(const fs::path& folder, std::vector<std::string>& notes) {
  const fs::path gradescope = gradescopeRoot(folder);
  std::vector<SubmissionResult> all =
      gradescope.empty() ? readBatch(folder, notes) : readGradescope(gradescope, notes);
  std::sort(all.begin(), all.end(),
            [](const SubmissionResult& a, const SubmissionResult& b) { return a.key < b.key; });
  return all;
}

int taskOfCheck(const std::string& check) {
  const std::size_t at = check.rfind("Golden", 0) == 0 ? 6 : 0;
  if (check.compare(at, 4, "Task") != 0 || check.size() <= at + 4) return 0;
  const char digit = check[at + 4];
  return std::isdigit(static_cast<unsigned char>(digit)) ? digit - '0' : 0;
}

namespace {

void addItems(const SubmissionResult& s, std::map<std::string, ItemStats>& items) {
  for (const ItemResult& item : s.items) {
    ItemStats& st = items[item.number + "\t" + item.name];
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
  std::map<std::string, MistakeStats> mistakes;
  for (const SubmissionResult& s : submissions) {
    if (!s.total) continue;
    ++c.graded;
    addItems(s, items);
    addMistakes(s, mistakes);
    for (const auto& [name, passed] : s.checks) {
      CheckStats& st = checks[name];
      st.name = name;
      st.task = taskOfCheck(name);
      ++st.ran;
      st.passed += passed;
    }
  }
  finishItems(items, c);
  for (auto& [name, st] : checks) c.checks.push_back(st);
  for (auto& [id, m] : mistakes) c.mistakes.push_back(m);
  std::stable_sort(
      c.mistakes.begin(), c.mistakes.end(),
      [](const MistakeStats& a, const MistakeStats& b) { return a.who.size() > b.who.size(); });
  flagChecks(c);
  c.submissions = std::move(submissions);
  return c;
}

}  // namespace a6::grader::insights
