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

}  // namespace

void plotLines(const char* id, const std::vector<PlotSeries>& series, float height,
               const char* unit, bool zeroBased, bool logScale) {
  // Symmetric log scale: sign(v) log10(1 + |v|), so that 1 J and 1e30 J fit in one plot.
  auto scaled = [logScale](float v) {
    return logScale ? std::copysign(std::log10(1.0f + std::abs(v)), v) : v;
  };
  auto unscaled = [logScale](float y) {
    return logScale ? std::copysign(std::pow(10.0f, std::abs(y)) - 1.0f, y) : y;
  };
  ImGui::PushID(id);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = std::max(ImGui::GetContentRegionAvail().x, 50.0f);
  const ImVec2 end(origin.x + width, origin.y + height);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, end, ImGui::GetColorU32(ImGuiCol_FrameBg));

  // The y range over every finite value, padded by 5 %.
  std::size_t count = 0;
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (const PlotSeries& s : series) {
    count = std::max(count, s.history->values().size());
    for (float v : s.history->values()) {
      if (std::isfinite(v)) {
        lo = std::min(lo, scaled(v));
        hi = std::max(hi, scaled(v));
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

  // The lines: x = frame slot (the newest at the right edge), gaps at non-finite values.
  const std::size_t slots = std::max<std::size_t>(count, 2);
  auto toScreen = [&](std::size_t k, std::size_t n, float v) {
    const float x = origin.x + width * (static_cast<float>(k + (slots - n)) / (slots - 1));
    const float y = end.y - height * ((scaled(v) - lo) / (hi - lo));
    return ImVec2(x, y);
  };
  draw->PushClipRect(origin, end, true);
  if (lo < 0 && hi > 0) {  // the zero line
    const float y = end.y - height * ((0 - lo) / (hi - lo));
    draw->AddLine(ImVec2(origin.x, y), ImVec2(end.x, y), ImGui::GetColorU32(ImGuiCol_Border));
  }
  for (const PlotSeries& s : series) {
    const std::vector<float>& v = s.history->values();
    for (std::size_t k = 1; k < v.size(); ++k) {
      if (std::isfinite(v[k - 1]) && std::isfinite(v[k])) {
        draw->AddLine(toScreen(k - 1, v.size(), v[k - 1]), toScreen(k, v.size(), v[k]), s.color,
                      1.5f);
      }
    }
  }
  draw->PopClipRect();
  draw->AddRect(origin, end, ImGui::GetColorU32(ImGuiCol_Border));
  // The range, on a backing so that the lines do not hide it.
  auto label = [&](float y, float v) {
    const std::string t = number(v, unit);
    const ImVec2 size = ImGui::CalcTextSize(t.c_str());
    const ImVec2 at(origin.x + 2, y);
    draw->AddRectFilled(at, ImVec2(at.x + size.x + 4, at.y + size.y),
                        ImGui::GetColorU32(ImGuiCol_WindowBg, 0.8f));
    draw->AddText(ImVec2(at.x + 2, at.y), ImGui::GetColorU32(ImGuiCol_TextDisabled), t.c_str());
  };
  label(origin.y + 1, unscaled(hi));
  label(end.y - ImGui::GetTextLineHeight() - 1, unscaled(lo));

  // Hover: every series at the frame under the cursor.
  ImGui::InvisibleButton("plot", ImVec2(width, height));
  if (ImGui::IsItemHovered() && count > 0) {
    const float t = (ImGui::GetIO().MousePos.x - origin.x) / width;
    const long slot = std::lround(t * (slots - 1));
    ImGui::BeginTooltip();
    for (const PlotSeries& s : series) {
      const std::vector<float>& v = s.history->values();
      const long k = slot - static_cast<long>(slots - v.size());
      if (k < 0 || k >= static_cast<long>(v.size())) continue;
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(s.color), "%s: %s", s.name,
                         number(v[k], unit).c_str());
    }
    ImGui::TextDisabled("%ld frames ago", static_cast<long>(slots) - 1 - slot);
    ImGui::EndTooltip();
  }

  // Legend with the latest values, on as many lines as the panel's width needs.
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
  ImGui::PopID();
}

}  // namespace a6::viewer
