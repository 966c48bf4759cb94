#include "report/replay_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/fixed.h"
#include "report/report.h"

namespace a6::assets {  // the page's assets, embedded at build time (a6_embedded_text)
extern const char replay_player_js[];
}  // namespace a6::assets

namespace a6::grader {
namespace {

constexpr const char* kStudentColor = "#e8710a";
constexpr const char* kReferenceColor = "#1a73e8";

// The player: decodes each replay's packed frames (render/replay.h) and draws them on canvases.
const char* const kPlayerScript =
    a6::assets::replay_player_js;  // grader/report/assets/replay_player.js (embedded)

// JSON inside <script>: no "</" that could end the element.
std::string scriptSafe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (const char c : json) {
    if (c == '<') {
      out += "\\u003c";
    } else {
      out += c;
    }
  }
  return out;
}

// The energy plot's range: the reference's, widened for the student's values by up to 1.5 of its
// span (further is off the chart: a run that blows up would flatten the rest).
std::pair<double, double> energyRange(const ReplayView& v) {
  const auto [rlo, rhi] = std::minmax_element(v.referenceEnergy.begin(), v.referenceEnergy.end());
  const double span = std::max(*rhi - *rlo, 1e-6 + 0.05 * std::abs(*rhi));
  double lo = *rlo - 0.1 * span, hi = *rhi + 0.1 * span;
  for (const double e : v.studentEnergy) {
    if (std::isfinite(e)) lo = std::min(lo, std::max(e, *rlo - 1.5 * span));
    if (std::isfinite(e)) hi = std::max(hi, std::min(e, *rhi + 1.5 * span));
  }
  return {lo, hi};
}

// The error plot's range: from 0 to the largest error, at least 4 and at most 50 thresholds.
std::pair<double, double> errorRange(const ReplayView& v) {
  double most = 0;
  for (const double e : v.error) {
    if (std::isfinite(e)) most = std::max(most, e);
  }
  return {0, std::clamp(most * 1.05, 4 * v.threshold, 50 * v.threshold)};
}

void player(std::ostringstream& out, const ReplayView& v) {
  out << "<div class=\"player\"><div class=\"views\"><figure><canvas width=\"300\" "
         "height=\"300\"></canvas><figcaption class=\"cap-left\">your run</figcaption></figure>"
         "<figure><canvas width=\"300\" height=\"300\"></canvas><figcaption>reference"
         "</figcaption></figure></div>\n<div class=\"controls\"><button class=\"play\">&#9654; "
         "play</button> <button class=\"prev\">&#9664; frame</button> <button class=\"next\">"
         "frame &#9654;</button> <input type=\"range\" min=\"0\" max=\"0\" value=\"0\"> <span "
         "class=\"time\"></span> <label><input type=\"checkbox\" class=\"overlay\"> "
         "overlay</label>";
  if (v.parted >= 0) out << " <button class=\"parted\">go to where they part</button>";
  out << "</div></div>\n";
}

void plots(std::ostringstream& out, const ReplayView& v) {
  const double mark = v.parted >= 0 ? v.times[static_cast<std::size_t>(v.parted)] : -1;
  out << "<div class=\"plots\">";
  if (!v.studentEnergy.empty()) {
    out << svgPlot("kinetic + potential energy", "J", v.times,
                   {{"yours", kStudentColor, false, &v.studentEnergy},
                    {"reference", kReferenceColor, true, &v.referenceEnergy}},
                   energyRange(v), NAN, mark);
  }
  out << svgPlot("position error: " + v.errorMeasure, "m", v.times,
                 {{"yours - reference", kStudentColor, false, &v.error}}, errorRange(v),
                 v.threshold, mark)
      << "</div>\n";
}

void replayBlock(std::ostringstream& out, const ReplayView& v) {
  out << "<section class=\"replay-box\" id=\"replay-" << htmlEscape(v.scene) << "\"><h3>"
      << htmlEscape(v.scene) << " <span class=\"tag\">task " << v.task << "</span></h3>\n";
  if (!v.missing.empty()) {
    out << "<p class=\"note\">No replay: " << htmlEscape(v.missing) << "</p></section>\n";
    return;
  }
  if (v.trajectory && v.task == 3) {
    out << "<p>This check's own input, run by your stepper and by the reference's, both with the "
           "reference forces.</p>\n";
  } else if (v.trajectory) {
    out << "<p>This check's own particles, updated by your particle system and by the "
           "reference's, both with the reference forces, stopped after each of "
        << v.frames.size() - 1 << " step counts.</p>\n";
  }
  out << "<p class=\"reading\">" << htmlEscape(v.reading) << "</p>\n";
  if (!v.divergence.empty())
    out << "<p class=\"reading\"><strong>First divergence:</strong> " << htmlEscape(v.divergence)
        << "</p>\n";
  out << "<div class=\"replay\">";
  player(out, v);
  plots(out, v);
  out << "<script type=\"application/json\" class=\"replay-data\">{\"parted\": " << v.parted
      << ", \"student\": " << scriptSafe(v.student)
      << ", \"reference\": " << scriptSafe(v.reference) << "}</script></div></section>\n";
}

}  // namespace

std::string withUnit(double value, const std::string& unit) {
  if (!std::isfinite(value)) return "not a number";
  char text[48];
  std::snprintf(text, sizeof text, "%.3g", value);
  return std::string(text) + (unit.empty() ? "" : " " + unit);
}

std::string svgPlot(const std::string& title, const std::string& unit,
                    const std::vector<double>& times, const std::vector<Series>& series,
                    std::pair<double, double> range, double level, double mark) {
  const double W = 460, H = 160, left = 64, right = 10, top = 32, bottom = 26;
  const double lo = range.first, hi = range.second > range.first ? range.second : lo + 1;
  const double t0 = times.empty() ? 0 : times.front(), t1 = times.empty() ? 1 : times.back();
  auto X = [&](double t) { return left + (t - t0) / std::max(t1 - t0, 1e-9) * (W - left - right); };
  auto Y = [&](double y) { return top + (hi - y) / (hi - lo) * (H - top - bottom); };
  std::ostringstream svg;
  svg << "<svg class=\"plot\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\""
      << H << "\" viewBox=\"0 0 " << W << " " << H << "\" role=\"img\" aria-label=\""
      << htmlEscape(title) << "\"><rect x=\"" << left << "\" y=\"" << top << "\" width=\""
      << W - left - right << "\" height=\"" << H - top - bottom
      << "\" fill=\"#fafafa\" stroke=\"#ccc\"/>"
      << "<text x=\"" << left << "\" y=\"14\" font-size=\"12\">" << htmlEscape(title) << "</text>"
      << "<text x=\"4\" y=\"" << top + 10 << "\" font-size=\"10\">" << withUnit(hi, unit)
      << "</text><text x=\"4\" y=\"" << H - bottom << "\" font-size=\"10\">" << withUnit(lo, unit)
      << "</text><text x=\"" << left << "\" y=\"" << H - 8 << "\" font-size=\"10\">" << fixed(t0, 2)
      << " s</text><text x=\"" << W - right - 40 << "\" y=\"" << H - 8 << "\" font-size=\"10\">"
      << fixed(t1, 2) << " s</text>";
  if (std::isfinite(level)) {
    svg << "<line x1=\"" << left << "\" x2=\"" << W - right << "\" y1=\"" << Y(level) << "\" y2=\""
        << Y(level) << "\" stroke=\"#999\" stroke-dasharray=\"2 3\"/>";
  }
  if (mark >= 0) {
    svg << "<line x1=\"" << X(mark) << "\" x2=\"" << X(mark) << "\" y1=\"" << top << "\" y2=\""
        << H - bottom << "\" stroke=\"#b3261e\"/>";
  }
  double legend = left;  // a line of its own, under the title
  for (const Series& s : series) {
    std::string path;
    bool pen = false;
    for (std::size_t k = 0; k < times.size() && k < s.values->size(); ++k) {
      const double y = (*s.values)[k];
      if (!std::isfinite(y)) {
        pen = false;
        continue;
      }
      path +=
          (pen ? " L" : " M") + fixed(X(times[k]), 1) + " " + fixed(Y(std::clamp(y, lo, hi)), 1);
      pen = true;
    }
    svg << "<path d=\"" << path << "\" fill=\"none\" stroke=\"" << s.color
        << "\" stroke-width=\"1.8\"" << (s.dashed ? " stroke-dasharray=\"5 3\"" : "") << "/>"
        << "<text x=\"" << legend << "\" y=\"27\" font-size=\"10\" fill=\"" << s.color << "\">"
        << htmlEscape(s.name) << "</text>";
    legend += 9 + 6.0 * static_cast<double>(s.name.size());
  }
  svg << "</svg>";
  return svg.str();
}

void htmlReplays(std::ostringstream& out, const std::vector<ReplayView>& replays) {
  if (replays.empty()) return;
  out << "<h2 id=\"replays\">Watch your simulation</h2>\n<p>Each scene the images check, run by "
         "your code (orange) beside the reference (blue): play it, drag the time, step frame by "
         "frame, or overlay the two. The plots show the energy and how far your positions are "
         "from the reference's; the red line marks where they part.</p>\n";
  for (const ReplayView& v : replays) {
    if (!v.trajectory) replayBlock(out, v);
  }
  if (std::any_of(replays.begin(), replays.end(), [](const ReplayView& v) { return v.trajectory; }))
    out << "<h3>Failed checks, replayed</h3>\n";
  for (const ReplayView& v : replays) {
    if (v.trajectory) replayBlock(out, v);
  }
  out << "<script>" << kPlayerScript << "</script>\n";
}

}  // namespace a6::grader
