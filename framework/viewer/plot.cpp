#include "viewer/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace a6::viewer {

void History::push(double value) {
  // Floats overflow to infinity long before an exploding cloth's doubles do: clamp, so the plot
  // shows the blow-up as a wall instead of a gap.
  constexpr double kLargest = 1e30;
  float v = std::numeric_limits<float>::quiet_NaN();
  if (std::isfinite(value)) v = static_cast<float>(std::clamp(value, -kLargest, kLargest));
  if (values_.size() >= capacity_) values_.erase(values_.begin());
  values_.push_back(v);
}

namespace {

std::string number(float v, const char* unit) {
  char text[64];
  if (std::isnan(v)) {
    std::snprintf(text, sizeof text, "not finite");
  } else {
    std::snprintf(text, sizeof text, "%.4g %s", v, unit);
  }
  return text;
}

// Symmetric log scale: sign(v) log10(1 + |v|), so that 1 J and 1e30 J fit in one plot.
float scaled(float v, bool logScale) {
  return logScale ? std::copysign(std::log10(1.0f + std::abs(v)), v) : v;
}

float unscaled(float y, bool logScale) {
  return logScale ? std::copysign(std::pow(10.0f, std::abs(y)) - 1.0f, y) : y;
}

// The plot's rectangle on screen and the y range it shows (scaled).
struct Frame {
  ImVec2 origin, end;
  float width = 0, height = 0;
  bool logScale = false;
  float lo = 0, hi = 1;
  std::size_t count = 0;  ///< values in the longest series
  std::size_t slots = 2;  ///< frame slots across the width: count, at least 2

  // Value k of a series of n, on screen: x = its frame slot (the newest at the right edge).
  ImVec2 toScreen(std::size_t k, std::size_t n, float v) const {
    const float x = origin.x + width * (static_cast<float>(k + (slots - n)) / (slots - 1));
    const float y = end.y - height * ((scaled(v, logScale) - lo) / (hi - lo));
    return ImVec2(x, y);
  }
};

// The y range over every finite value, padded by 5 %.
void fitRange(const std::vector<PlotSeries>& series, bool zeroBased, Frame& f) {
  std::size_t count = 0;
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (const PlotSeries& s : series) {
    count = std::max(count, s.history->values().size());
    for (float v : s.history->values()) {
      if (std::isfinite(v)) {
        lo = std::min(lo, scaled(v, f.logScale));
        hi = std::max(hi, scaled(v, f.logScale));
      }
    }
  }
  if (zeroBased) {
    lo = std::min(lo, 0.0f);
    hi = std::max(hi, 0.0f);
  }
  if (!(lo <= hi)) lo = 0, hi = 1;
  if (hi - lo < 1e-12f * std::max(1.0f, std::abs(hi))) {
    lo -= 0.5f;
    hi += 0.5f;
  }
  const float pad = 0.05f * (hi - lo);
  lo -= zeroBased && lo == 0 ? 0 : pad;
  hi += pad;
  f.lo = lo;
  f.hi = hi;
  f.count = count;
  f.slots = std::max<std::size_t>(count, 2);
}

// The zero line and the series, gaps at non-finite values, then the frame's border.
void drawLines(const Frame& f, const std::vector<PlotSeries>& series, ImDrawList* draw) {
  draw->PushClipRect(f.origin, f.end, true);
  if (f.lo < 0 && f.hi > 0) {
    const float y = f.end.y - f.height * ((0 - f.lo) / (f.hi - f.lo));
    draw->AddLine(ImVec2(f.origin.x, y), ImVec2(f.end.x, y), ImGui::GetColorU32(ImGuiCol_Border));
  }
  for (const PlotSeries& s : series) {
    const std::vector<float>& v = s.history->values();
    for (std::size_t k = 1; k < v.size(); ++k) {
      if (std::isfinite(v[k - 1]) && std::isfinite(v[k])) {
        draw->AddLine(f.toScreen(k - 1, v.size(), v[k - 1]), f.toScreen(k, v.size(), v[k]), s.color,
                      1.5f);
      }
    }
  }
  draw->PopClipRect();
  draw->AddRect(f.origin, f.end, ImGui::GetColorU32(ImGuiCol_Border));
}

// The range's two ends, on a backing so that the lines do not hide them.
void drawRange(const Frame& f, const char* unit, ImDrawList* draw) {
  auto label = [&](float y, float v) {
    const std::string t = number(v, unit);
    const ImVec2 size = ImGui::CalcTextSize(t.c_str());
    const ImVec2 at(f.origin.x + 2, y);
    draw->AddRectFilled(at, ImVec2(at.x + size.x + 4, at.y + size.y),
                        ImGui::GetColorU32(ImGuiCol_WindowBg, 0.8f));
    draw->AddText(ImVec2(at.x + 2, at.y), ImGui::GetColorU32(ImGuiCol_TextDisabled), t.c_str());
  };
  label(f.origin.y + 1, unscaled(f.hi, f.logScale));
  label(f.end.y - ImGui::GetTextLineHeight() - 1, unscaled(f.lo, f.logScale));
}

// Hover: every series at the frame under the cursor.
void hoverTooltip(const Frame& f, const std::vector<PlotSeries>& series, const char* unit) {
  ImGui::InvisibleButton("plot", ImVec2(f.width, f.height));
  if (!ImGui::IsItemHovered() || f.count == 0) return;
  const float t = (ImGui::GetIO().MousePos.x - f.origin.x) / f.width;
  const long slot = std::lround(t * (f.slots - 1));
  ImGui::BeginTooltip();
  for (const PlotSeries& s : series) {
    const std::vector<float>& v = s.history->values();
    const long k = slot - static_cast<long>(f.slots - v.size());
    if (k < 0 || k >= static_cast<long>(v.size())) continue;
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(s.color), "%s: %s", s.name,
                       number(v[k], unit).c_str());
  }
  ImGui::TextDisabled("%ld frames ago", static_cast<long>(f.slots) - 1 - slot);
  ImGui::EndTooltip();
}

// Legend with the latest values, on as many lines as the panel's width needs.
void legend(const std::vector<PlotSeries>& series, const char* unit) {
  const float right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
  for (std::size_t k = 0; k < series.size(); ++k) {
    const History& h = *series[k].history;
    const std::string text =
        std::string(series[k].name) + " " + (h.empty() ? "-" : number(h.last(), unit));
    if (k > 0) {
      ImGui::SameLine();
      if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x +
              ImGui::CalcTextSize(text.c_str()).x >
          right) {
        ImGui::NewLine();
      }
    }
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(series[k].color), "%s", text.c_str());
  }
}

}  // namespace

void plotLines(const char* id, const std::vector<PlotSeries>& series, float height,
               const char* unit, bool zeroBased, bool logScale) {
  ImGui::PushID(id);
  Frame f;
  f.origin = ImGui::GetCursorScreenPos();
  f.width = std::max(ImGui::GetContentRegionAvail().x, 50.0f);
  f.height = height;
  f.end = ImVec2(f.origin.x + f.width, f.origin.y + height);
  f.logScale = logScale;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(f.origin, f.end, ImGui::GetColorU32(ImGuiCol_FrameBg));
  fitRange(series, zeroBased, f);
  drawLines(f, series, draw);
  drawRange(f, unit, draw);
  hoverTooltip(f, series, unit);
  legend(series, unit);
  ImGui::PopID();
}

}  // namespace a6::viewer
