// Grading a folder of submissions, the second half: each grading's outcome, read back from its
// results.json, and the gradebook and the summary. See batch.h; the layouts are in layouts.cpp.
#include "batch/batch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

namespace a6::grader::batch {

using Json = nlohmann::ordered_json;

namespace {

std::string number(double x) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(4) << std::round(x * 1e4) / 1e4;
  std::string s = out.str();
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

Json optionalNumber(const std::optional<double>& x) { return x ? Json(*x) : Json(nullptr); }

std::optional<double> numberOf(const Json& j) {
  return j.is_number() ? std::optional<double>(j.get<double>()) : std::nullopt;
}

// extra_data.incidents as lines for a TA: "the code crashed 2 times", ...
std::vector<std::string> flagsOf(const Json& incidents) {
  std::vector<std::string> flags;
  auto add = [&](const char* key, const std::string& what) {
    const double n = incidents.is_object() ? numberOf(incidents.value(key, Json())).value_or(0) : 0;
    if (!(n > 0)) return;
    std::ostringstream line;
    line << what << " " << n << (n == 1 ? " time" : " times");
    flags.push_back(line.str());
  };
  add("crashes", "the code crashed");
  add("timeouts", "the code ran out of time");
  add("start_failures", "the program did not start");
  return flags;
}

// The task a test's tags name, 0 for none; and whether they say extra credit.
std::pair<int, bool> taskOfTags(const Json& tags) {
  int task = 0;
  bool extraCredit = false;
  for (const Json& tag : tags) {
    if (!tag.is_string()) continue;
    const std::string s = tag.get<std::string>();
    if (s == "extra_credit") extraCredit = true;
    if (const int t = courseTasks().ofTag(s); t > 0) task = t;
  }
  return {task, extraCredit};
}

// The points of the tests summed per task and as extra credit, and the maximum, into `o`
// (extra_data's own maximum and extra credit win when given).
void pointsOfTests(const Json& tests, const Json& extra, Outcome& o) {
  double max = 0, extraCredit = 0;
  std::vector<double> tasks(o.tasks.size());
  for (const Json& t : tests) {
    const double score = t.value("score", 0.0);
    max += t.value("max_score", 0.0);
    const auto [task, isExtra] = taskOfTags(t.value("tags", Json::array()));
    if (isExtra) {
      extraCredit += score;
    } else if (task > 0 && static_cast<std::size_t>(task) <= tasks.size()) {
      tasks[static_cast<std::size_t>(task - 1)] += score;
    }
  }
  o.max = numberOf(extra.value("max_score", Json())).value_or(max);
  o.extraCredit = numberOf(extra.value("extra_credit", Json())).value_or(extraCredit);
  for (std::size_t i = 0; i < tasks.size(); ++i) o.tasks[i] = std::round(tasks[i] * 1e4) / 1e4;
}

// Which task files fell back to the starter, and why, from extra_data.build (file -> status):
// "no task file in the submission", "spring.cpp, forces.cpp compile error; ...", or "".
std::string brokenBuild(const Json& extra) {
  std::vector<std::pair<std::string, std::string>> byStatus;  // status -> its files, in order
  int missing = 0, files = 0;
  if (extra.contains("build") && extra["build"].is_object()) {
    for (const auto& [file, status] : extra["build"].items()) {
      const std::string s = status.is_string() ? status.get<std::string>() : status.dump();
      ++files;
      if (s == "compiled") continue;
      missing += s == "missing";
      auto it = std::find_if(byStatus.begin(), byStatus.end(),
                             [&](const auto& b) { return b.first == s; });
      if (it == byStatus.end()) it = byStatus.insert(byStatus.end(), {s, ""});
      it->second += (it->second.empty() ? "" : ", ") + file;
    }
  }
  if (missing > 0 && missing == files) return "no task file in the submission";
  std::string broken;
  for (const auto& [status, list] : byStatus) {
    broken += (broken.empty() ? "" : "; ") + list + " " + status;
  }
  return broken;
}

// The ids of extra_data.mistakes ([{"task": 1, "mistake": "t1_wrong_sign", ...}, ...]), or of a
// marker's list of ids.
std::vector<std::string> mistakesOf(const Json& list) {
  std::vector<std::string> ids;
  if (!list.is_array()) return ids;
  for (const Json& m : list) {
    const Json id = m.is_object() ? m.value("mistake", Json()) : m;
    if (id.is_string() && !id.get<std::string>().empty()) ids.push_back(id.get<std::string>());
  }
  return ids;
}

}  // namespace

Outcome outcomeOfResults(const std::string& resultsJson) {
  Outcome o;
  const Json r = Json::parse(resultsJson, nullptr, false);
  if (r.is_discarded() || !r.is_object() || !r.contains("score") || !r["score"].is_number() ||
      !r.contains("tests") || !r["tests"].is_array()) {
    o.reason = resultsJson.empty() ? "a6_grade wrote no results.json"
                                   : "a6_grade's results.json is not valid";
    return o;
  }
  const Json extra = r.value("extra_data", Json::object());
  // a6_grade's own errors (its placeholder from the start of a run says it did not finish).
  if (extra.contains("errors") && extra["errors"].is_array() && !extra["errors"].empty()) {
    o.reason = extra["errors"][0].is_string() ? extra["errors"][0].get<std::string>()
                                              : extra["errors"][0].dump();
    return o;
  }
  o.total = r["score"].get<double>();
  if (extra.contains("refused") && extra["refused"].is_string()) {
    o.status = kNotGraded;
    o.reason = extra["refused"].get<std::string>();
    o.max = numberOf(extra.value("max_score", Json()));
    return o;
  }
  o.flags = flagsOf(extra.value("incidents", Json::object()));
  o.mistakes = mistakesOf(extra.value("mistakes", Json::array()));
  pointsOfTests(r["tests"], extra, o);
  o.reason = brokenBuild(extra);
  o.status = o.reason.empty() ? kGraded : kBuildFailed;
  return o;
}

std::string markerJson(const std::string& fingerprint, const Outcome& o) {
  Json j;
  j["fingerprint"] = fingerprint;
  j["status"] = o.status;
  j["total"] = optionalNumber(o.total);
  j["max"] = optionalNumber(o.max);
  Json tasks = Json::array();
  for (const auto& t : o.tasks) tasks.push_back(optionalNumber(t));
  j["tasks"] = tasks;
  j["extra_credit"] = optionalNumber(o.extraCredit);
  j["seconds"] = std::round(o.seconds * 100) / 100;
  j["reason"] = o.reason;
  j["flags"] = o.flags;
  j["mistakes"] = o.mistakes;
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::optional<Outcome> outcomeOfMarker(const std::string& markerText,
                                       const std::string& fingerprint) {
  const Json j = Json::parse(markerText, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("fingerprint", "") != fingerprint ||
      !j.contains("status") || !j["status"].is_string()) {
    return std::nullopt;
  }
  Outcome o;
  o.status = j["status"].get<std::string>();
  o.total = numberOf(j.value("total", Json()));
  o.max = numberOf(j.value("max", Json()));
  const Json tasks = j.value("tasks", Json::array());
  for (std::size_t i = 0; i < o.tasks.size() && i < tasks.size(); ++i)
    o.tasks[i] = numberOf(tasks[i]);
  o.extraCredit = numberOf(j.value("extra_credit", Json()));
  o.seconds = numberOf(j.value("seconds", Json())).value_or(0);
  o.reason = j.value("reason", "");
  for (const Json& flag : j.value("flags", Json::array())) {
    if (flag.is_string()) o.flags.push_back(flag.get<std::string>());
  }
  o.mistakes = mistakesOf(j.value("mistakes", Json::array()));
  return o;
}

std::string csvField(const std::string& text) {
  const bool quote = text.find_first_of(",\"\r\n") != std::string::npos ||
                     (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!quote) return text;
  std::string out = "\"";
  for (const char c : text) {
    out += c;
    if (c == '"') out += '"';
  }
  return out + "\"";
}

std::string gradebookCsv(const std::vector<std::pair<const Submission*, const Outcome*>>& graded,
                         const TaskTable& tasks) {
  std::string csv = "student,email,sid,total,max,";
  for (const Task& t : tasks.all()) csv += tasks.tag(t.number) + ",";
  csv += "extra_credit,status,seconds,mistakes\r\n";
  auto num = [](const std::optional<double>& x) { return x ? number(*x) : std::string(); };
  for (const auto& [s, o] : graded) {
    for (const Person& p : s->people) {
      csv += csvField(p.name) + "," + csvField(p.email) + "," + csvField(p.sid) + ",";
      csv += num(o->total) + "," + num(o->max) + ",";
      for (std::size_t t = 0; t < static_cast<std::size_t>(tasks.count()); ++t)
        csv += num(t < o->tasks.size() ? o->tasks[t] : std::nullopt) + ",";
      csv += num(o->extraCredit) + "," + csvField(o->status) + ",";
      std::ostringstream seconds;
      seconds << std::fixed << std::setprecision(1) << o->seconds;
      std::string mistakes;
      for (const std::string& m : o->mistakes) mistakes += (mistakes.empty() ? "" : " ") + m;
      csv += seconds.str() + "," + csvField(mistakes) + "\r\n";
    }
  }
  return csv;
}

std::string mistakeCounts(const std::vector<const Outcome*>& outcomes) {
  std::map<std::string, int> count;
  for (const Outcome* o : outcomes) {
    for (const std::string& m : o->mistakes) ++count[m];
  }
  std::vector<std::pair<int, std::string>> ranked;
  for (const auto& [id, n] : count) ranked.emplace_back(-n, id);
  std::sort(ranked.begin(), ranked.end());
  std::ostringstream out;
  for (const auto& [minus, id] : ranked) {
    out << "    " << std::left << std::setw(40) << id << std::right << std::setw(5) << -minus
        << (minus == -1 ? " submission" : " submissions") << "\n";
  }
  return out.str();
}

std::string histogram(const std::vector<double>& totals) {
  if (totals.empty()) return "";
  std::map<int, int> bins;
  int top = 0;
  for (const double t : totals) {
    const int bin = std::max(0, static_cast<int>(std::floor(t / 10 + 1e-9)));
    ++bins[bin];
    top = std::max(top, bin);
  }
  int most = 0;
  for (const auto& [bin, n] : bins) most = std::max(most, n);
  const double scale = most > 50 ? 50.0 / most : 1.0;  // bars at most 50 wide
  std::ostringstream out;
  for (int b = 0; b <= top; ++b) {
    const int n = bins.count(b) ? bins[b] : 0;
    const std::string label = std::to_string(b * 10) + "-" + std::to_string(b * 10 + 9);
    const int width = n == 0 ? 0 : std::max(1, static_cast<int>(std::lround(n * scale)));
    out << "    " << std::setw(7) << label << " | "
        << std::string(static_cast<std::size_t>(width), '#')
        << (n > 0 ? " " + std::to_string(n) : "") << "\n";
  }
  return out.str();
}

std::string duration(double seconds) {
  const long s = std::max(0L, std::lround(seconds));
  char buf[32];
  if (s >= 3600) {
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  } else if (s >= 60) {
    std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%lds", s);
  }
  return buf;
}

}  // namespace a6::grader::batch
