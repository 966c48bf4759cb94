#include "report/replay_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/fixed.h"
#include "report/report.h"

namespace a6::grader {
namespace {

constexpr const char* kStudentColor = "#e8710a";
constexpr const char* kReferenceColor = "#1a73e8";

// The player: decodes each replay's packed frames (render/replay.h) and draws them on canvases.
const char* const kPlayerScript = R"JS(
(function () {
  function decode(b64) {
    var s = atob(b64), n = s.length >> 1, a = new Int16Array(n);
    for (var i = 0; i < n; i++) {
      var u = s.charCodeAt(2 * i) | (s.charCodeAt(2 * i + 1) << 8);
      a[i] = u > 32767 ? u - 65536 : u;
    }
    return a;
  }
  function prepare(run) {
    run.pts = decode(run.data);
    run.shapePts = run.shapes.reduce(function (n, s) { return n + s[1]; }, 0);
    run.at = [];
    var at = 0;
    run.counts.forEach(function (c) { run.at.push(at); at += 2 * (c[0] + run.shapePts + 4 * c[1]); });
  }
  function draw(ctx, run, f, color, background) {
    var W = ctx.canvas.width, H = ctx.canvas.height, v = run.view, s = H / v[2], u = run.unit;
    if (background) {
      ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, W, H);
      ctx.strokeStyle = '#999'; ctx.fillStyle = '#eee'; ctx.lineWidth = 1.5;
      run.planes.forEach(function (p) {
        var cx = p[0] * p[2], cy = p[1] * p[2], tx = -p[1] * 4 * v[2], ty = p[0] * 4 * v[2];
        ctx.beginPath();
        ctx.moveTo(W / 2 + (cx - tx - v[0]) * s, H / 2 - (cy - ty - v[1]) * s);
        ctx.lineTo(W / 2 + (cx + tx - v[0]) * s, H / 2 - (cy + ty - v[1]) * s);
        ctx.stroke();
      });
      run.circles.forEach(function (c) {
        ctx.beginPath();
        ctx.arc(W / 2 + (c[0] - v[0]) * s, H / 2 - (c[1] - v[1]) * s, c[2] * s, 0, 2 * Math.PI);
        ctx.fill(); ctx.stroke();
      });
    }
    if (f >= run.counts.length) return;
    var d = run.pts, base = run.at[f], n = run.counts[f][0], m = run.counts[f][1];
    function pt(i) {
      var x = d[base + 2 * i], y = d[base + 2 * i + 1];
      if (x === -32768 || y === -32768) return null;
      return [W / 2 + x * u * s, H / 2 - y * u * s];
    }
    ctx.strokeStyle = color; ctx.fillStyle = color; ctx.globalAlpha = 0.55; ctx.lineWidth = 1;
    ctx.beginPath();
    for (var k = 0; k + 2 < run.springs.length; k += 3) {
      var a = run.springs[k], b = run.springs[k + 1];
      if (a >= n || b >= n) continue;
      var pa = pt(a), pb = pt(b);
      if (pa && pb) { ctx.moveTo(pa[0], pa[1]); ctx.lineTo(pb[0], pb[1]); }
    }
    ctx.stroke();
    ctx.globalAlpha = 1;
    var r = Math.max(1.5, Math.min(6, run.radius * s));
    for (var i = 0; i < n; i++) {
      var p = pt(i);
      if (p) { ctx.beginPath(); ctx.arc(p[0], p[1], r, 0, 2 * Math.PI); ctx.fill(); }
    }
    var at = n;
    ctx.lineWidth = 2;
    run.shapes.forEach(function (sh) {
      ctx.beginPath();
      if (sh[0] === 0) {
        var c = pt(at), rim = pt(at + 1);
        if (c && rim) {
          ctx.arc(c[0], c[1], sh[2] * s, 0, 2 * Math.PI);
          ctx.moveTo(c[0], c[1]); ctx.lineTo(rim[0], rim[1]);
        }
      } else {
        for (var q = 0; q < sh[1]; q++) {
          var pq = pt(at + q);
          if (pq) { if (q === 0) ctx.moveTo(pq[0], pq[1]); else ctx.lineTo(pq[0], pq[1]); }
        }
        if (sh[0] === 1) ctx.closePath();
      }
      ctx.stroke();
      at += sh[1];
    });
    ctx.setLineDash([4, 3]);
    for (var j = 0; j < m; j++) {
      ctx.beginPath();
      for (var e = 0; e < 4; e++) {
        var pj = pt(at + 4 * j + e);
        if (pj) { if (e === 0) ctx.moveTo(pj[0], pj[1]); else ctx.lineTo(pj[0], pj[1]); }
      }
      ctx.stroke();
    }
    ctx.setLineDash([]);
  }
  document.querySelectorAll('.replay').forEach(function (box) {
    var data = JSON.parse(box.querySelector('script.replay-data').textContent);
    var mine = data.student, ref = data.reference;
    prepare(mine); prepare(ref);
    var canvases = box.querySelectorAll('canvas'), left = canvases[0].getContext('2d'),
        right = canvases[1].getContext('2d');
    var slider = box.querySelector('input[type=range]'), label = box.querySelector('.time'),
        overlay = box.querySelector('input.overlay'), play = box.querySelector('.play');
    var last = mine.frames.length - 1, f = 0, timer = null;
    slider.max = last;
    function show(k) {
      f = Math.max(0, Math.min(last, k));
      slider.value = f;
      var both = overlay.checked;
      if (both) { draw(left, ref, f, '#1a73e8', true); draw(left, mine, f, '#e8710a', false); }
      else { draw(left, mine, f, '#e8710a', true); draw(right, ref, f, '#1a73e8', true); }
      canvases[1].parentNode.style.display = both ? 'none' : '';
      box.querySelector('.cap-left').textContent = both ? 'yours (orange) over the reference (blue)' : 'your run';
      var t = (mine.frames[f] * mine.frameDt).toFixed(2);
      label.textContent = 't = ' + t + ' s, frame ' + mine.frames[f] +
          (data.parted >= 0 && f >= data.parted ? '  (parted)' : '');
    }
    function stop() { if (timer) { clearInterval(timer); timer = null; } play.textContent = '\u25B6 play'; }
    play.onclick = function () {
      if (timer) { stop(); return; }
      if (f >= last) show(0);
      play.textContent = '\u23F8 pause';
      timer = setInterval(function () { if (f >= last) stop(); else show(f + 1); }, 100);
    };
    box.querySelector('.prev').onclick = function () { stop(); show(f - 1); };
    box.querySelector('.next').onclick = function () { stop(); show(f + 1); };
    var parted = box.querySelector('.parted');
    if (parted) parted.onclick = function () { stop(); show(data.parted); };
    slider.oninput = function () { stop(); show(+slider.value); };
    overlay.onchange = function () { show(f); };
    show(data.parted >= 0 ? data.parted : 0);
  });
})();
)JS";

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
  out << "<p class=\"reading\">" << htmlEscape(v.reading) << "</p>\n<div class=\"replay\">";
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
