// A small line plot for Dear ImGui: several series over the same frames, one shared y scale,
// a legend with the latest values and a tooltip with every series at the hovered frame.
// (ImGui::PlotLines draws one series per plot; kinetic and potential energy read best together.)
#pragma once

#include <imgui.h>

#include <cstddef>
#include <string>
#include <vector>

namespace a6::viewer {

/// The last `capacity` values of a quantity, oldest first. Non-finite values are kept (as NaN)
/// and leave a gap in the plot.
class History {
 public:
  explicit History(std::size_t capacity = 600) : capacity_(capacity) {}
  void push(double value);
  void clear() { values_.clear(); }
  const std::vector<float>& values() const { return values_; }
  bool empty() const { return values_.empty(); }
  float last() const { return values_.empty() ? 0.0f : values_.back(); }

 private:
  std::size_t capacity_;
  std::vector<float> values_;
};

struct PlotSeries {
  const char* name;
  const History* history;
  ImU32 color;
};

/// Draws the series as lines in a frame `height` pixels high and the panel's width. `unit` is
/// appended to the numbers ("J", "ms"). With zeroBased the y range always includes 0; with
/// logScale the y axis is sign(v) log10(1 + |v|) (an exploding cloth reaches 1e30 J).
void plotLines(const char* id, const std::vector<PlotSeries>& series, float height,
               const char* unit, bool zeroBased, bool logScale = false);

}  // namespace a6::viewer
