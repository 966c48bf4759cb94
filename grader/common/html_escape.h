// Text made safe to put in an HTML page's text or a quoted attribute: & < > " ' escaped, NUL as
// U+FFFD. The report, the replays' page and the insights write every text a submission could
// have set through it.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace a6::grader {

inline std::string htmlEscape(const std::string& text) {
  static const std::map<char, std::string_view> kEntities = {{'&', "&amp;"},  {'<', "&lt;"},
                                                             {'>', "&gt;"},   {'"', "&quot;"},
                                                             {'\'', "&#39;"}, {'\0', "&#xFFFD;"}};
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (const char c : text) {
    const auto e = kEntities.find(c);
    out += e == kEntities.end() ? std::string_view(&c, 1) : e->second;
  }
  return out;
}

}  // namespace a6::grader
