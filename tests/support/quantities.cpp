#include "quantities.h"

#include <cctype>
#include <map>
#include <regex>

namespace a6::test {
namespace {

// The last member or function of an expression, and what it names.
const std::map<std::string, Quantity>& table() {
  static const std::map<std::string, Quantity> names = {
      {"forceOf", {"the force on p2", "N"}},
      {"total", {"externalForce, the sum of the forces", "N"}},
      {"gravity", {"the gravity force", "N"}},
      {"buoyancy", {"the buoyancy force", "N"}},
      {"drag", {"the drag force", "N"}},
      {"repulsion", {"the repulsion force", "N"}},
      {"x", {"position", "m"}},
      {"v", {"velocity", "m/s"}},
      {"m", {"mass", "kg"}},
      {"age", {"age", "s"}},
      {"lifetime", {"lifetime", "s"}},
      {"temperature", {"temperature", "K"}},
      {"restLength", {"rest length", "m"}},
      {"ks", {"spring constant ks", "N/m"}},
      {"kd", {"damping coefficient kd", "N·s/m"}},
      {"anchorA", {"joint's anchor on body A (world)", "m"}},
      {"anchorB", {"joint's anchor on body B (world)", "m"}},
      {"localAxisA", {"joint's axis in body A's frame", ""}},
      {"stiffness", {"joint's stiffness", "N/m"}},
      {"damping", {"joint's damping", "N·s/m"}},
      {"motorSpeed", {"motor's speed", ""}},
      {"maxMotor", {"motor's largest force or torque", ""}},
      {"lower", {"lower limit", ""}},
      {"upper", {"upper limit", ""}},
      {"length", {"joint's length", "m"}},
      {"minLength", {"joint's shortest length", "m"}},
      {"maxLength", {"joint's longest length", "m"}},
      {"maxForce", {"mouse joint's largest force", "N"}},
      {"target", {"mouse joint's target", "m"}},
      {"reactionForce", {"joint's reaction force on body B", "N"}},
      {"period", {"period", "s"}},
      {"reached", {"position the piston reached", "m"}},
  };
  return names;
}

// "result.particles[0].v" -> "particle 0's "; "s[1].x" -> "particle 1's "; else "".
std::string owner(const std::string& expression) {
  static const std::regex indexed(R"((particles|s)\[([0-9a-z]+)\]\.[A-Za-z]+$)");
  std::smatch m;
  if (std::regex_search(expression, m, indexed)) return "particle " + m[2].str() + "'s ";
  return "";
}

}  // namespace

Quantity quantityOf(const std::string& expression) {
  // The last identifier once the calls' arguments are gone: a member after '.', or a function.
  static const std::regex arguments(R"(\([^()]*\))");
  std::string e = expression;
  for (std::string before; before != e;) before = e, e = std::regex_replace(e, arguments, "");
  std::size_t end = e.size();
  while (end > 0 && !std::isalnum(static_cast<unsigned char>(e[end - 1])) && e[end - 1] != '_')
    --end;
  std::size_t start = end;
  while (start > 0 &&
         (std::isalnum(static_cast<unsigned char>(e[start - 1])) || e[start - 1] == '_'))
    --start;
  const auto found = table().find(e.substr(start, end - start));
  if (found == table().end()) return {"the value checked", ""};
  Quantity q = found->second;
  q.words = owner(expression) + q.words;
  return q;
}

}  // namespace a6::test
