#include "rubric/rubric.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "common/limits.h"

namespace a6::grader {

const char* toString(Visibility v) {
  switch (v) {
    case Visibility::Visible:
      return "visible";
    case Visibility::Hidden:
      return "hidden";
    case Visibility::AfterDueDate:
      return "after_due_date";
    case Visibility::AfterPublished:
      return "after_published";
  }
  return "visible";
}

bool globMatch(const std::string& pattern, const std::string& text) {
  // Iterative matcher with one backtrack point (the last '*'): linear in practice.
  std::size_t p = 0, t = 0, starP = std::string::npos, starT = 0;
  while (t < text.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
      ++p, ++t;
    } else if (p < pattern.size() && pattern[p] == '*') {
      starP = p++;
      starT = t;
    } else if (starP != std::string::npos) {
      p = starP + 1;
      t = ++starT;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

bool RubricItem::matches(const std::string& testName) const {
  return std::any_of(tests.begin(), tests.end(),
                     [&](const std::string& glob) { return globMatch(glob, testName); });
}

int Rubric::itemFor(const std::string& testName) const {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].matches(testName)) return static_cast<int>(i);
  }
  return -1;
}

namespace {

// Levenshtein distance, for "did you mean" suggestions on misspelt keys.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string suggestion(const std::string& key, const std::vector<std::string>& known) {
  std::string best;
  std::size_t bestDistance = 3;  // suggest only close misspellings
  for (const std::string& candidate : known) {
    const std::size_t d = editDistance(key, candidate);
    if (d < bestDistance) bestDistance = d, best = candidate;
  }
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

std::string typeName(toml::node_type type) {
  switch (type) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    default:
      return "a date or time";
  }
}

bool parseVisibility(const std::string& text, Visibility& out) {
  for (Visibility v : {Visibility::Visible, Visibility::Hidden, Visibility::AfterDueDate,
                       Visibility::AfterPublished}) {
    if (text == toString(v)) {
      out = v;
      return true;
    }
  }
  return false;
}

// Collects every problem with its line, so that a TA fixes the file in one pass.
class Checker {
 public:
  Checker(std::string source, const TaskTable& tasks) : source_(std::move(source)), tasks_(tasks) {}

  /// The tasks an item may name.
  const TaskTable& tasks() const { return tasks_; }

  void error(int line, const std::string& what) {
    std::ostringstream out;
    out << source_;
    if (line > 0) out << ":" << line;
    out << ": " << what;
    errors_.push_back(out.str());
  }
  static int lineOf(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

  bool number(const toml::node& node, const std::string& where, double& out) {
    if (const auto v = node.value<double>(); v && (node.is_integer() || node.is_floating_point())) {
      out = *v;
      if (std::isfinite(out)) return true;
      error(lineOf(node), where + " must be a finite number");
      return false;
    }
    error(lineOf(node), where + " must be a number, not " + typeName(node.type()));
    return false;
  }
  // `out` from a node of TOML type T, or an error: "WHERE must be WHAT, not a ...".
  template <class T, class Out>
  bool typed(const toml::node& node, const std::string& where, const char* what, Out& out) {
    if (node.is<T>()) {
      out = *node.value<T>();
      return true;
    }
    error(lineOf(node), where + " must be " + what + ", not " + typeName(node.type()));
    return false;
  }
  bool integer(const toml::node& node, const std::string& where, long long& out) {
    return typed<std::int64_t>(node, where, "an integer", out);
  }
  bool boolean(const toml::node& node, const std::string& where, bool& out) {
    return typed<bool>(node, where, "true or false", out);
  }
  bool string(const toml::node& node, const std::string& where, std::string& out) {
    return typed<std::string>(node, where, "a string", out);
  }
  bool visibility(const toml::node& node, const std::string& where, Visibility& out) {
    std::string text;
    if (!string(node, where, text)) return false;
    if (parseVisibility(text, out)) return true;
    error(lineOf(node), where + " is '" + text +
                            "': use one of visible, hidden, after_due_date, after_published");
    return false;
  }
  bool timeLimit(const toml::node& node, const std::string& where, double& out) {
    if (!number(node, where, out)) return false;
    if (out > 0 && out <= kMaxCheckTimeLimit) return true;
    error(lineOf(node), where + " must be more than 0 and at most " +
                            secondsText(kMaxCheckTimeLimit) + " seconds");
    return false;
  }

  std::string joined() const {
    std::string text;
    for (const std::string& e : errors_) text += (text.empty() ? "" : "\n") + e;
    return text;
  }
  bool clean() const { return errors_.empty(); }

 private:
  std::string source_;
  const TaskTable& tasks_;
  std::vector<std::string> errors_;
};

const std::vector<std::string> kTopKeys = {"title", "total", "visibility", "time_limit", "item"};
const std::vector<std::string> kItemKeys = {"name",       "task",           "tests",
                                            "points",     "all_or_nothing", "extra_credit",
                                            "visibility", "time_limit",     "checks"};

// An item's `task`: a task of the table (harness/tasks.h), or 0 for none.
void parseTask(const toml::node& node, int line, const std::string& where, Checker& check,
               RubricItem& item) {
  long long task = 0;
  if (check.integer(node, where, task)) {
    const int count = check.tasks().count();
    if (task < 0 || task > count) {
      check.error(line, where + " must be 1.." + std::to_string(count) + ", or 0 for none");
    }
    item.task = static_cast<int>(task);
  }
}

// An item's `tests`: one glob, or a list of them.
void parseTests(const toml::node& node, int line, const std::string& where, Checker& check,
                RubricItem& item) {
  if (node.is_string()) {
    item.tests.push_back(*node.value<std::string>());
  } else if (const toml::array* array = node.as_array()) {
    for (const toml::node& glob : *array) {
      std::string text;
      if (check.string(glob, "each glob in " + where, text)) item.tests.push_back(text);
    }
  } else {
    check.error(line,
                where + " must be a glob string or a list of them, not " + typeName(node.type()));
  }
}

void parseItemKey(const std::string& k, const toml::node& node, int line, const std::string& label,
                  Checker& check, RubricItem& item) {
  const std::string where = "'" + k + "' of " + label;
  if (k == "name") {
    check.string(node, where, item.name);
  } else if (k == "task") {
    parseTask(node, line, where, check, item);
  } else if (k == "tests") {
    parseTests(node, line, where, check, item);
  } else if (k == "points") {
    if (check.number(node, where, item.points) && item.points < 0) {
      check.error(
          line, where + " is negative (" + std::to_string(item.points) + "): points are 0 or more");
    }
  } else if (k == "all_or_nothing") {
    check.boolean(node, where, item.allOrNothing);
  } else if (k == "extra_credit") {
    check.boolean(node, where, item.extraCredit);
  } else if (k == "visibility") {
    check.visibility(node, where, item.visibility);
  } else if (k == "time_limit") {
    check.timeLimit(node, where, item.timeLimitSeconds);
  } else if (k == "checks") {
    long long count = 0;
    if (check.integer(node, where, count) && (count < 0 || count > 100000))
      check.error(line, where + " must be a count of checks, 0 or more");
    item.checks = static_cast<int>(count);
  } else {
    check.error(line, "unknown key '" + k + "' in " + label + suggestion(k, kItemKeys) +
                          "; an item has: name, task, tests, points, all_or_nothing, "
                          "extra_credit, visibility, time_limit, checks");
  }
}

// The keys every item must have, and no empty glob.
void checkItemComplete(const toml::table& table, const std::string& label, const RubricItem& item,
                       Checker& check) {
  if (!table.contains("name")) check.error(item.line, label + " has no 'name'");
  if (!table.contains("tests")) check.error(item.line, label + " has no 'tests' (a glob)");
  if (!table.contains("points")) check.error(item.line, label + " has no 'points'");
  if (table.contains("tests") && item.tests.empty()) {
    check.error(item.line, label + " has an empty 'tests' list");
  }
  for (const std::string& glob : item.tests) {
    if (glob.empty()) check.error(item.line, label + " has an empty glob in 'tests'");
  }
}

void parseItem(const toml::table& table, int index, Visibility defaultVisibility,
               double defaultTimeLimit, Checker& check, Rubric& rubric) {
  RubricItem item;
  item.visibility = defaultVisibility;
  item.timeLimitSeconds = defaultTimeLimit;
  item.line = static_cast<int>(table.source().begin.line);
  const std::string label = "[[item]] " + std::to_string(index);
  for (auto&& [key, node] : table) {
    parseItemKey(std::string(key.str()), node, static_cast<int>(key.source().begin.line), label,
                 check, item);
  }
  checkItemComplete(table, label, item, check);
  rubric.items.push_back(std::move(item));
}

struct ItemDefaults {
  Visibility visibility = Visibility::Visible;
  double timeLimit = kDefaultTimeLimit;
};

// The top-level keys (the defaults apply to every item, wherever they appear).
ItemDefaults parseTopLevel(const toml::table& root, Checker& check, Rubric& rubric) {
  ItemDefaults defaults;
  bool haveTotal = false;
  for (auto&& [key, node] : root) {
    const std::string k(key.str());
    const int line = static_cast<int>(key.source().begin.line);
    if (k == "title") {
      check.string(node, "'title'", rubric.title);
    } else if (k == "total") {
      haveTotal = check.number(node, "'total'", rubric.totalPoints);
      if (haveTotal && rubric.totalPoints < 0) check.error(line, "'total' is negative");
    } else if (k == "visibility") {
      check.visibility(node, "'visibility'", defaults.visibility);
    } else if (k == "time_limit") {
      check.timeLimit(node, "'time_limit'", defaults.timeLimit);
    } else if (k != "item") {
      check.error(line, "unknown top-level key '" + k + "'" + suggestion(k, kTopKeys) +
                            "; the top level has: title, total, visibility, time_limit, "
                            "[[item]]");
    }
  }
  if (!haveTotal && !root.contains("total")) {
    check.error(0, "no 'total': say how many points the rubric is out of (e.g. total = 100)");
  }
  return defaults;
}

void parseItems(const toml::table& root, const ItemDefaults& defaults, Checker& check,
                Rubric& rubric) {
  const toml::node* items = root.get("item");
  if (items == nullptr) return;
  const toml::array* array = items->as_array();
  if (array == nullptr || !array->is_array_of_tables()) {
    check.error(Checker::lineOf(*items), "'item' must be written as [[item]] tables");
    return;
  }
  int index = 0;
  for (const toml::node& node : *array) {
    parseItem(*node.as_table(), ++index, defaults.visibility, defaults.timeLimit, check, rubric);
  }
}

// What holds across items: names unique (they are the test names in results.json), and the
// total what the regular items add up to.
void checkAcrossItems(const toml::table& root, Checker& check, const Rubric& rubric) {
  std::set<std::string> names;
  for (const RubricItem& item : rubric.items) {
    if (!item.name.empty() && !names.insert(item.name).second) {
      check.error(item.line, "two items are named '" + item.name + "': names must be unique");
    }
  }
  if (!check.clean()) return;
  double sum = 0;
  for (const RubricItem& item : rubric.items) {
    if (!item.extraCredit) sum += item.points;
  }
  if (std::abs(sum - rubric.totalPoints) > 1e-9) {
    std::ostringstream out;
    out << "total = " << rubric.totalPoints << " but the items' points add up to " << sum
        << " (extra credit not counted): fix the total or the points";
    check.error(static_cast<int>(root.get("total")->source().begin.line), out.str());
  }
}

}  // namespace

Rubric parseRubric(const std::string& text, const std::string& sourceName, const TaskTable& tasks) {
  Rubric rubric;
  rubric.file = sourceName;
  Checker check(sourceName, tasks);
  toml::table root;
  try {
    root = toml::parse(text, sourceName);
  } catch (const toml::parse_error& e) {
    check.error(static_cast<int>(e.source().begin.line),
                "not valid TOML: " + std::string(e.description()));
    rubric.error = check.joined();
    return rubric;
  }
  const ItemDefaults defaults = parseTopLevel(root, check, rubric);
  parseItems(root, defaults, check, rubric);
  if (rubric.items.empty() && check.clean()) check.error(0, "no [[item]]: nothing to score");
  checkAcrossItems(root, check, rubric);
  rubric.error = check.joined();
  return rubric;
}

Rubric loadRubric(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    Rubric rubric;
    rubric.file = file;
    rubric.error = file.string() + ": cannot read the rubric file (does it exist?)";
    return rubric;
  }
  std::ostringstream text;
  text << in.rdbuf();
  Rubric rubric = parseRubric(text.str(), file.string());
  rubric.file = file;
  return rubric;
}

bool RubricItem::onHiddenChecks() const {
  if (tests.empty()) return false;
  for (const std::string& glob : tests) {
    // Every suite of the tasks' table that the glob's suite part can match is a hidden one
    // ("Task*Hidden.*" too), and it matches one at least.
    const std::string suitePart = glob.substr(0, glob.find('.'));
    int matched = 0;
    for (const auto& [suite, owner] : courseTasks().suites()) {
      if (!globMatch(suitePart, suite)) continue;
      if (!isHidden(owner.kind)) return false;
      ++matched;
    }
    if (matched == 0) return false;
  }
  return true;
}

namespace {
// A TOML basic string.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string number(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  std::string text = out.str();
  if (text.find_first_of(".eE") == std::string::npos && text.find("inf") == std::string::npos) {
    text += ".0";
  }
  return text;
}
}  // namespace

std::string publicRubricToml(const Rubric& rubric) {
  double total = 0, hidden = 0;
  for (const RubricItem& item : rubric.items) {
    if (item.extraCredit) continue;
    (item.onHiddenChecks() ? hidden : total) += item.points;
  }
  std::ostringstream out;
  out << "# The public rubric: the graders' rubric without the items of the hidden checks, which\n"
         "# run only when your submission is graded. Written by a6_grade --public-rubric from "
      << rubric.file.filename().string()
      << ";\n# do not edit (scripts/check.sh grades your files with it).\n\n";
  // The title heads the report: it says that the grader checks more than this rubric does.
  std::ostringstream title;
  title << rubric.title;
  if (hidden > 0)
    title << " (public checks; the grader's hidden checks add " << hidden << " points)";
  out << "title = " << quoted(title.str()) << "\n";
  out << "total = " << number(total) << "\n";
  for (const RubricItem& item : rubric.items) {
    if (item.onHiddenChecks()) continue;
    out << "\n[[item]]\n";
    out << "name = " << quoted(item.name) << "\n";
    out << "task = " << item.task << "\n";
    out << "tests = [";
    for (std::size_t k = 0; k < item.tests.size(); ++k)
      out << (k ? ", " : "") << quoted(item.tests[k]);
    out << "]\n";
    out << "points = " << number(item.points) << "\n";
    if (item.allOrNothing) out << "all_or_nothing = true\n";
    if (item.extraCredit) out << "extra_credit = true\n";
    out << "visibility = " << quoted(toString(item.visibility)) << "\n";
    out << "time_limit = " << number(item.timeLimitSeconds) << "\n";
  }
  return out.str();
}

}  // namespace a6::grader
