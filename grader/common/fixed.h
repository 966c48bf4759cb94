// A number with a fixed count of decimals, as the reports and the batch's lines print times
// and points ("12.50").
#pragma once

#include <cstdio>
#include <string>

namespace a6::grader {

inline std::string fixed(double x, int digits) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, x);
  return text;
}

}  // namespace a6::grader
