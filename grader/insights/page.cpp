// insights.html. See page.h.
#include "insights/page.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

#include "common/atomic_write.h"
#include "common/html_escape.h"

namespace a6::assets {  // the page's assets, embedded at build time (a6_embedded_text)
extern const char insights_css[];
extern const char sort_tables_js[];
}  // namespace a6::assets

namespace a6::grader::insights {
namespace {

const char* const kCss =
    a6::assets::insights_css;  // grader/insights/assets/insights.css (embedded)

// Sorts a table by the column whose header was clicked: by each cell's data-v when it has
// one (numbers), else by its text; a second click reverses.
const char* const kScript =
    a6::assets::sort_tables_js;  // grader/insights/assets/sort_tables.js (embedded)

std::string fmt(double x, int digits = 2) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s;
}

std::string percent(double fraction) { return fmt(100 * fraction, 0) + " %"; }

// A cell with a sort value and a bar of `fraction` (0..1) before the text.
std::string barCell(double fraction, const std::string& text) {
  const bool low = fraction < 0.5;
  return "<td data-v=\"" + fmt(fraction, 4) + "\"><span class=\"barbox\"><span class=\"bar" +
         std::string(low ? " low" : "") + "\" style=\"width:" + fmt(100 * fraction, 1) +
         "%\"></span></span>" + text + "</td>";
}

std::string numCell(double x, int digits = 2) {
  return "<td class=\"num\" data-v=\"" + fmt(x, 4) + "\">" + fmt(x, digits) + "</td>";
}

// Percent-encodes a relative link (a6_batch's folder names are safe already; this keeps it so).
std::string hrefOf(const std::string& path) {
  static const char* const hex = "0123456789ABCDEF";
  std::string out;
  for (const unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '.' || c == '-' || c == '_') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

// An SVG bar chart of `values` in `bins` equal bins over [0, max] (the last bin holds max).
std::string histogramSvg(const std::vector<double>& values, double max, int bins) {
  bins = std::max(bins, 1);
  std::vector<int> count(static_cast<std::size_t>(bins), 0);
  for (const double v : values) {
    const double at = max <= 0 ? 0 : std::clamp(v / max, 0.0, 1.0) * bins;
    ++count[static_cast<std::size_t>(std::min(static_cast<int>(at), bins - 1))];
  }
  const int highest = std::max(1, *std::max_element(count.begin(), count.end()));
  const int w = 22, h = 120, left = 28, bottom = 30;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << left + bins * w + 10
      << "\" height=\"" << h + bottom + 10 << "\" role=\"img\">";
  svg << "<text x=\"2\" y=\"12\">" << highest << "</text><text x=\"2\" y=\"" << h + 10
      << "\">0</text>";
  for (int i = 0; i < bins; ++i) {
    const int n = count[static_cast<std::size_t>(i)];
    const int bar = n * h / highest;
    const int x = left + i * w;
    svg << "<rect x=\"" << x + 1 << "\" y=\"" << 10 + h - bar << "\" width=\"" << w - 2
        << "\" height=\"" << bar << "\" fill=\"#5b8def\"><title>" << fmt(max * i / bins, 1)
        << " to " << fmt(max * (i + 1) / bins, 1) << ": " << n << "</title></rect>";
    if (n > 0)
      svg << "<text x=\"" << x + w / 2 - 3 << "\" y=\"" << 8 + h - bar << "\">" << n << "</text>";
    if (i % 2 == 0) {
      svg << "<text x=\"" << x << "\" y=\"" << h + 24 << "\">" << fmt(max * i / bins, 0)
          << "</text>";
    }
  }
  svg << "<line x1=\"" << left << "\" y1=\"" << h + 10 << "\" x2=\"" << left + bins * w
      << "\" y2=\"" << h + 10 << "\" stroke=\"#888\"/></svg>";
  return svg.str();
}

// A submission's regular points in task `task` (its extra credit apart, as in the gradebook).
double regularPoints(const SubmissionResult& s, int task) {
  double sum = 0;
  for (const ItemResult& item : s.items)
    sum += item.task == task && !item.extraCredit ? item.score : 0;
  return sum;
}

void distributions(std::ostringstream& out, const ClassInsights& c) {
  std::vector<double> totals;
  double max = 0;
  for (const SubmissionResult& s : c.submissions) {
    if (!s.total) continue;
    totals.push_back(*s.total);
    max = std::max({max, s.max + s.extraCredit, *s.total});
  }
  out << "<h2 id=\"distribution\">Distribution of totals</h2>\n<div class=\"plots\"><figure>"
      << histogramSvg(totals, max, 20) << "<figcaption>total (extra credit included), "
      << totals.size() << " graded</figcaption></figure></div>\n<div class=\"plots\">";
  std::set<int> tasks;
  for (const ItemStats& item : c.items) {
    if (item.task > 0 && !item.extraCredit && item.points > 0) tasks.insert(item.task);
  }
  for (const int task : tasks) {  // each graded submission's regular points, and the task's worth
    double worth = 0;
    for (const ItemStats& item : c.items) {
      if (item.task == task && !item.extraCredit) worth += item.points;
    }
    std::vector<double> points;
    for (const SubmissionResult& s : c.submissions) {
      if (s.total) points.push_back(regularPoints(s, task));
    }
    out << "<figure>" << histogramSvg(points, worth, 10) << "<figcaption>task " << task << " (of "
        << fmt(worth) << " points)</figcaption></figure>";
  }
  out << "</div>\n";
}

void itemsTable(std::ostringstream& out, const ClassInsights& c) {
  out << "<h2 id=\"items\">Rubric items</h2>\n<p>Every item of the rubric: how many got all of "
         "it, its mean, and the points the class lost on it (extra credit: not earned).</p>\n"
         "<table class=\"sortable\"><thead><tr><th>item</th><th>task</th><th>worth</th>"
         "<th>all of it</th><th>mean</th><th>points lost</th></tr></thead><tbody>\n";
  for (const ItemStats& item : c.items) {
    const double rate = item.graded == 0 ? 0 : double(item.full) / item.graded;
    out << "<tr><td>" << htmlEscape(item.name) << "</td>" << numCell(item.task, 0)
        << numCell(item.points)
        << barCell(rate, std::to_string(item.full) + " of " + std::to_string(item.graded))
        << numCell(item.mean) << numCell(item.lost) << "</tr>\n";
  }
  out << "</tbody></table>\n";
}

void checksTable(std::ostringstream& out, const ClassInsights& c) {
  std::map<std::string, bool> flagged;
  for (const Flag& f : c.flags) flagged[f.check] = f.nearlyAllFail;
  out << "<h2 id=\"checks\">Checks</h2>\n<p>Each check the gradings ran, with how many passed it "
         "and the points it cost the class (a grading's points lost on an item, shared among the "
         "item's checks it failed).</p>\n<table class=\"sortable\"><thead><tr><th>check</th>"
         "<th>task</th><th>passed</th><th>failed</th><th>points lost</th></tr></thead><tbody>\n";
  for (const CheckStats& check : c.checks) {
    const auto f = flagged.find(check.name);
    const bool look = f != flagged.end() && f->second;
    out << "<tr" << (look ? " class=\"flag\"" : "") << "><td><code>" << htmlEscape(check.name)
        << "</code></td>" << numCell(check.task, 0)
        << barCell(check.passRate(),
                   std::to_string(check.passed) + " of " + std::to_string(check.ran))
        << numCell(check.ran - check.passed, 0)
        << (check.costed() ? numCell(check.lost) : "<td class=\"num\" data-v=\"-1\">–</td>")
        << "</tr>\n";
  }
  out << "</tbody></table>\n";
}

void flagsSection(std::ostringstream& out, const ClassInsights& c) {
  out << "<h2 id=\"look\">Checks to look at</h2>\n";
  if (c.graded < kFlagMinimum) {
    out << "<p class=\"note\">Only " << c.graded << " graded submissions: checks are judged in a "
        << "class of " << kFlagMinimum << " or more.</p>\n";
    return;
  }
  std::vector<std::string> fail, pass;
  for (const Flag& f : c.flags) (f.nearlyAllFail ? fail : pass).push_back(f.check);
  out << "<p>Nearly everyone fails (at most " << percent(kNearlyAllFail)
      << " pass): is the check broken, or was the lesson missed?</p><ul>";
  for (const std::string& check : fail) out << "<li><code>" << htmlEscape(check) << "</code></li>";
  if (fail.empty()) out << "<li class=\"note\">none</li>";
  out << "</ul>\n<details><summary>Everyone passes (" << pass.size()
      << " checks): do they catch anything?</summary><ul>";
  for (const std::string& check : pass) out << "<li><code>" << htmlEscape(check) << "</code></li>";
  out << "</ul></details>\n";
}

void mistakesSection(std::ostringstream& out, const ClassInsights& c) {
  out << "<h2 id=\"mistakes\">Named mistakes</h2>\n";
  if (c.mistakes.empty()) {
    out << "<p class=\"note\">No known mistake was named for any submission.</p>\n";
    return;
  }
  out << "<p>The known mistakes (grader/mistakes/) the reports named, with what one student was "
         "told.</p>\n<table class=\"sortable\"><thead><tr><th>mistake</th><th>task</th>"
         "<th>submissions</th><th>example message</th><th>who</th></tr></thead><tbody>\n";
  for (const MistakeStats& m : c.mistakes) {
    std::string who;
    for (const std::string& k : m.who) who += (who.empty() ? "" : ", ") + htmlEscape(k);
    out << "<tr><td><code>" << htmlEscape(m.id) << "</code></td>" << numCell(m.task, 0)
        << numCell(static_cast<double>(m.who.size()), 0) << "<td>" << htmlEscape(m.example)
        << "</td><td>" << who << "</td></tr>\n";
  }
  out << "</tbody></table>\n";
}

// The class by diagnosed part (mistakes/measure.h): which parts of the slide's laws the
// measurement found wrong, whatever the catalogue named.
void partsSection(std::ostringstream& out, const ClassInsights& c) {
  out << "<h2 id=\"parts\">Diagnosed parts</h2>\n";
  if (c.parts.empty()) {
    out << "<p class=\"note\">The measurement found no part wrong in any submission.</p>\n";
    return;
  }
  out << "<p>The parts the grader's measurement found wrong (the task and the parts; "
         "<code>_measured</code>: differs, no single change explains it), with what one student "
         "was told.</p>\n<table class=\"sortable\"><thead><tr><th>parts</th><th>task</th>"
         "<th>submissions</th><th>example message</th><th>who</th></tr></thead><tbody>\n";
  for (const MistakeStats& m : c.parts) {
    std::string who;
    for (const std::string& k : m.who) who += (who.empty() ? "" : ", ") + htmlEscape(k);
    out << "<tr><td><code>" << htmlEscape(m.id) << "</code></td>" << numCell(m.task, 0)
        << numCell(static_cast<double>(m.who.size()), 0) << "<td>" << htmlEscape(m.example)
        << "</td><td>" << who << "</td></tr>\n";
  }
  out << "</tbody></table>\n";
}

void incidentsSection(std::ostringstream& out, const ClassInsights& c) {
  out << "<h2 id=\"incidents\">Incidents</h2>\n<table class=\"sortable\"><thead><tr><th>"
         "submission</th><th>what happened</th></tr></thead><tbody>\n";
  int rows = 0;
  for (const SubmissionResult& s : c.submissions) {
    std::vector<std::string> what;
    if (!s.problem.empty()) what.push_back(s.problem);
    if (!s.build.empty()) what.push_back("did not compile: " + s.build + " (the starter's used)");
    if (s.incidents.crashes > 0) what.push_back(std::to_string(s.incidents.crashes) + " crashes");
    if (s.incidents.timeouts > 0)
      what.push_back(std::to_string(s.incidents.timeouts) + " time-outs");
    if (s.incidents.startFailures > 0)
      what.push_back(std::to_string(s.incidents.startFailures) + " failed starts of its probe");
    if (what.empty()) continue;
    std::string text;
    for (const std::string& w : what) text += (text.empty() ? "" : "; ") + htmlEscape(w);
    out << "<tr><td>" << htmlEscape(s.key) << "</td><td>" << text << "</td></tr>\n";
    ++rows;
  }
  if (rows == 0) out << "<tr><td colspan=\"2\" class=\"note\">none</td></tr>\n";
  out << "</tbody></table>\n";
}

void submissionsTable(std::ostringstream& out, const ClassInsights& c) {
  std::set<int> tasks;
  for (const ItemStats& item : c.items) {
    if (item.task > 0) tasks.insert(item.task);
  }
  out << "<h2 id=\"submissions\">Submissions</h2>\n<p>Each task's regular points (its extra "
         "credit is in the total).</p><table class=\"sortable\"><thead><tr>"
         "<th>submission</th><th>total</th>";
  for (const int task : tasks) out << "<th>task " << task << "</th>";
  out << "<th>mistakes</th><th>report</th></tr></thead><tbody>\n";
  for (const SubmissionResult& s : c.submissions) {
    out << "<tr><td>" << htmlEscape(s.key) << "</td>";
    if (s.total) {
      out << numCell(*s.total);
    } else {
      out << "<td data-v=\"-1\">" << htmlEscape(s.problem) << "</td>";
    }
    for (const int task : tasks) out << numCell(regularPoints(s, task));
    std::set<std::string> named;
    std::string mistakes;
    for (const ItemResult& item : s.items) {
      if (!item.mistake.empty() && named.insert(item.mistake).second)
        mistakes += (mistakes.empty() ? "" : " ") + item.mistake;
    }
    out << "<td>" << htmlEscape(mistakes) << "</td><td>";
    if (!s.report.empty()) out << "<a href=\"" << hrefOf(s.report) << "\">report.html</a>";
    out << "</td></tr>\n";
  }
  out << "</tbody></table>\n";
}

void passage(std::ostringstream& out, const SimilarPair& p, const SharedPassage& s) {
  out << "<div class=\"side\"><pre><b>" << htmlEscape(p.a) << "</b>, lines " << s.firstA << "-"
      << s.lastA << "\n"
      << htmlEscape(s.textA) << "</pre><pre><b>" << htmlEscape(p.b) << "</b>, lines " << s.firstB
      << "-" << s.lastB << "\n"
      << htmlEscape(s.textB) << "</pre></div>\n";
}

void similaritySection(std::ostringstream& out, const SimilarityReport* r) {
  out << "<h2 id=\"similarity\">Similarity</h2>\n";
  if (r == nullptr) {
    out << "<p class=\"note\">Not compared: run <code>a6_batch --similarity</code> (or "
           "<code>a6_insights --similarity</code>) to compare the submissions' task files.</p>\n";
    return;
  }
  out << "<p>" << htmlEscape(r->tool.empty() ? "no similarity tool" : r->tool) << ", "
      << r->compared << " files compared task file by task file on this machine; runs of at least "
      << r->minimumRun
      << " tokens, the starter's text and the passages common in the class left out. Pairs whose "
         "shared rare code covers at least "
      << r->threshold << " % of one file's own code (at least 4 lines):</p>\n";
  for (const std::string& n : r->notes) out << "<p class=\"note\">" << htmlEscape(n) << "</p>\n";
  if (r->pairs.empty() && !r->stopped)
    out << "<p class=\"note\">No pair above the threshold.</p>\n";
  for (const SimilarPair& p : r->pairs) {
    out << "<div class=\"pair\"><p><b>" << htmlEscape(p.a) << "</b> and <b>" << htmlEscape(p.b)
        << "</b>: <code>" << htmlEscape(p.taskFile) << "</code>, " << p.percent << " %</p>\n";
    for (const SharedPassage& s : p.passages) passage(out, p, s);
    out << "</div>\n";
  }
}

void header(std::ostringstream& out, const ClassInsights& c, const PageInput& in) {
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>"
      << htmlEscape(in.title) << ": class insights</title><style>" << kCss
      << "</style></head><body>\n"
      << "<h1>" << htmlEscape(in.title) << ": class insights</h1>\n<p>" << c.submissions.size()
      << " submissions, " << c.graded << " with a grade, read from <code>" << htmlEscape(in.source)
      << "</code>.";
  std::vector<double> totals;
  for (const SubmissionResult& s : c.submissions) {
    if (s.total) totals.push_back(*s.total);
  }
  if (!totals.empty()) {
    std::sort(totals.begin(), totals.end());
    const double sum = std::accumulate(totals.begin(), totals.end(), 0.0);
    out << " Mean " << fmt(sum / totals.size()) << ", median "
        << fmt((totals[(totals.size() - 1) / 2] + totals[totals.size() / 2]) / 2) << ".";
  }
  out << "</p>\n";
  for (const std::string& n : in.notes) out << "<p class=\"note\">" << htmlEscape(n) << "</p>\n";
  out << "<p><a href=\"#distribution\">distribution</a> &middot; <a href=\"#items\">rubric items"
         "</a> &middot; <a href=\"#look\">checks to look at</a> &middot; <a href=\"#mistakes\">"
         "mistakes</a> &middot; <a href=\"#parts\">diagnosed parts</a> &middot; <a "
         "href=\"#incidents\">incidents</a> &middot; <a href=\"#similarity"
         "\">similarity</a> &middot; <a href=\"#submissions\">submissions</a> &middot; <a href=\""
         "#checks\">checks</a></p>\n";
}

}  // namespace

std::string insightsHtml(const ClassInsights& c, const PageInput& in) {
  std::ostringstream out;
  header(out, c, in);
  distributions(out, c);
  itemsTable(out, c);
  flagsSection(out, c);
  mistakesSection(out, c);
  partsSection(out, c);
  incidentsSection(out, c);
  similaritySection(out, in.similarity);
  submissionsTable(out, c);
  checksTable(out, c);
  out << "<script>" << kScript << "</script>\n</body></html>\n";
  return out.str();
}

std::string writeInsights(const std::filesystem::path& folder, const std::filesystem::path& page,
                          PageInput input) {
  std::vector<std::string> notes;
  ClassInsights c = summarize(readFolder(folder, notes));
  for (const SubmissionResult& s : c.submissions) {
    if (input.title.empty() && !s.rubric.empty()) input.title = s.rubric;
  }
  if (input.title.empty()) input.title = "Assignment 6";
  if (input.source.empty()) input.source = folder.string();
  input.notes.insert(input.notes.end(), notes.begin(), notes.end());
  return writeFileAtomically(page, insightsHtml(c, input));
}

}  // namespace a6::grader::insights
