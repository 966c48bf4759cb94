// The report's replays: per imaged scene, the student's run beside the reference's in a small
// player, with SVG plots of the energy and the position error. One script, no network.
#pragma once

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "replay/replay_view.h"

namespace a6::grader {

/// The "Watch your simulation" section (nothing when there is no replay).
void htmlReplays(std::ostringstream& out, const std::vector<ReplayView>& replays);

/// One inline SVG line plot (public for the tests): `series` drawn over `times`, each with its
/// colour and dash, within `range` (values beyond it on its edge); a dashed level line at
/// `level` when finite; a red mark at `mark` s when >= 0.
struct Series {
  std::string name, color;
  bool dashed = false;
  const std::vector<double>* values = nullptr;
};
std::string svgPlot(const std::string& title, const std::string& unit,
                    const std::vector<double>& times, const std::vector<Series>& series,
                    std::pair<double, double> range, double level, double mark);

/// A number for people: three significant digits and its unit ("0.0123 m", "-4.56 J").
std::string withUnit(double value, const std::string& unit);

}  // namespace a6::grader
