// Task 4 measured: two cloths built into a system that holds the prelude (so base = 3), set
// beside the reference builder's, spring by spring (by their ends, in either order): which
// springs are missing or extra (by type and grid offset), which are typed wrongly, their rest
// lengths and constants by type, and the pins. Each finding counts what was measured.
#include "reference/cloth.h"

#include <limits>
#include <map>
#include <optional>
#include <set>

#include "mistakes/library/measured/tasks.h"

namespace a6::grader::measured {
namespace {

using harness::ClothRequest;
using harness::ClothResult;

ClothSpec clothSpec(int k) {
  ClothSpec s;
  s.n = k == 0 ? 3 : 4;
  s.size = k == 0 ? 1.5 : 2.0;
  s.origin = Vec2(1, 2);
  s.particleMass = 0.02;
  s.ksStructural = 200, s.kdStructural = 0.2;
  s.shear = true, s.ksShear = 50, s.kdShear = 0.05;
  s.bending = k == 0, s.ksBending = 20, s.kdBending = 0.02;
  return s;
}

const char* typeName(SpringType t) {
  switch (t) {
    case SpringType::Structural:
      return "structural";
    case SpringType::Shear:
      return "shear";
    case SpringType::Bending:
      return "bending";
    default:
      return "other";
  }
}

using Key = std::pair<int, int>;  // a spring's ends, the lower first

Key keyOf(const SpringData& s) { return {std::min(s.i, s.j), std::max(s.i, s.j)}; }

// The cloth's springs by their ends (the prelude's left out).
std::multimap<Key, SpringData> springsOf(const ClothResult& r) {
  std::multimap<Key, SpringData> out;
  const int base = static_cast<int>(harness::clothPrelude().particles.size());
  for (const SpringData& s : r.springs) {
    if (s.type == SpringType::Other && std::max(s.i, s.j) < base) continue;
    out.emplace(keyOf(s), s);
  }
  return out;
}

// A spring's place in the grid, "(i, j)-(i', j')", or its indices where an end is outside it.
std::string placeOf(const Key& k, const ClothSpec& spec) {
  const int base = static_cast<int>(harness::clothPrelude().particles.size());
  const int count = (spec.n + 1) * (spec.n + 1);
  const auto at = [&](int index) {
    const long long c = static_cast<long long>(index) - base;  // a student's index may be any
    if (c < 0 || c >= count) return "particle " + std::to_string(index);
    return "(" + std::to_string(c % (spec.n + 1)) + ", " + std::to_string(c / (spec.n + 1)) + ")";
  };
  return at(k.first) + "-" + at(k.second);
}

// What one cloth shows: counted differences, each a sentence.
struct ClothCount {
  std::map<std::string, int> missing, extra, mistyped, doubled;
  std::map<std::string, std::string> missingExample, extraExample;
  std::map<std::string, std::set<std::string>> restLength, constants;
  std::string pins;
};

void countSprings(const ClothResult& yours, const ClothResult& ref, const ClothSpec& spec,
                  ClothCount& c) {
  const auto mine = springsOf(yours), theirs = springsOf(ref);
  for (const auto& [key, s] : theirs) {
    const auto found = mine.find(key);
    const std::string type = typeName(s.type);
    if (found == mine.end()) {
      if (c.missing[type]++ == 0) c.missingExample[type] = placeOf(key, spec);
      continue;
    }
    const SpringData& m = found->second;
    if (mine.count(key) > 1) ++c.doubled[type];
    if (m.type != s.type) ++c.mistyped[type + " springs typed " + typeName(m.type)];
    if (std::abs(m.restLength - s.restLength) > 1e-6 * s.restLength)
      c.restLength[type].insert(number(m.restLength / s.restLength));
    if (!(std::abs(m.ks - s.ks) <= 1e-6 * s.ks) || !(std::abs(m.kd - s.kd) <= 1e-6 * s.kd))
      c.constants[type].insert("ks = " + number(m.ks) + ", kd = " + number(m.kd) + " where the " +
                               "spec gives ks = " + number(s.ks) + ", kd = " + number(s.kd));
  }
  for (const auto& [key, s] : mine) {
    if (theirs.count(key) > 0) continue;
    const std::string type = typeName(s.type);
    if (c.extra[type]++ == 0) c.extraExample[type] = placeOf(key, spec);
  }
}

// The pinned particles' places, "(0, 3) and (3, 3)".
std::string pinnedPlaces(const ClothResult& r, const ClothSpec& spec) {
  std::string out;
  for (std::size_t k = 0; k < r.particles.size(); ++k) {
    if (!r.particles[k].pinned) continue;
    const std::string place = placeOf({static_cast<int>(k), static_cast<int>(k)}, spec);
    out += (out.empty() ? "" : " and ") + place.substr(0, place.find('-'));
  }
  return out.empty() ? "none" : out;
}

// Whether every cloth spring of `yours` is the reference's with both ends `base` lower.
bool numberedFromZero(const ClothResult& yours, const ClothResult& ref) {
  const int base = static_cast<int>(harness::clothPrelude().particles.size());
  const auto mine = springsOf(yours), theirs = springsOf(ref);
  if (mine.empty() || mine.size() != theirs.size()) return false;
  for (const auto& [key, s] : mine) {
    if (key.second > std::numeric_limits<int>::max() - base ||
        theirs.count({key.first + base, key.second + base}) == 0)
      return false;
  }
  return true;
}

// The cloth's particles where they differ from the reference's: their count, a place, a mass.
std::optional<Finding> particlesDiffer(const ClothResult& yours, const ClothResult& ref,
                                       const ClothSpec& spec) {
  Finding f;
  f.verdict = Verdict::Unexplained;
  f.tag = "particles", f.part = "cloth's particles";
  if (yours.particles.size() != ref.particles.size()) {
    f.measured = std::to_string(yours.particles.size()) + " particles in the system where the " +
                 "physics' has " + std::to_string(ref.particles.size());
    return f;
  }
  for (std::size_t k = 0; k < ref.particles.size(); ++k) {
    const Particle &a = yours.particles[k], &b = ref.particles[k];
    if ((a.x - b.x).norm() <= 1e-6 * (1 + b.x.norm()) && std::abs(a.m - b.m) <= 1e-6 * b.m)
      continue;
    const std::string place = placeOf({static_cast<int>(k), static_cast<int>(k)}, spec);
    f.measured = "particle " + place.substr(0, place.find('-')) + " at " + vector(a.x) +
                 " with m = " + number(a.m) + ", the physics' at " + vector(b.x) +
                 " with m = " + number(b.m);
    return f;
  }
  return std::nullopt;
}

Finding differs(const std::string& tag, const std::string& part, const std::string& how) {
  Finding f;
  f.verdict = Verdict::Differs;
  f.tag = tag, f.part = part, f.how = how;
  return f;
}

void addCounts(const ClothCount& c, std::vector<Finding>& out) {
  for (const auto& [type, k] : c.missing)
    out.push_back(differs("missing_" + type, "cloth's " + type + " springs",
                          "leave out " + std::to_string(k) + " springs the slide has (such as " +
                              c.missingExample.at(type) + ")"));
  for (const auto& [type, k] : c.extra)
    out.push_back(differs("extra_" + type, "cloth's " + type + " springs",
                          "add " + std::to_string(k) +
                              " springs the slide does not have (such as " +
                              c.extraExample.at(type) + ")"));
  for (const auto& [what, k] : c.mistyped)
    out.push_back(
        differs("mistyped", "cloth's springs", "include " + std::to_string(k) + " " + what));
  for (const auto& [type, k] : c.doubled)
    out.push_back(differs("doubled_" + type, "cloth's " + type + " springs",
                          "are each made twice (" + std::to_string(k) + " of them)"));
  for (const auto& [type, ratios] : c.restLength)
    out.push_back(differs("rest_" + type, "cloth's " + type + " springs",
                          ratios.size() == 1
                              ? "have rest lengths " + *ratios.begin() + " times the physics'"
                              : "have rest lengths that differ from the physics'"));
  for (const auto& [type, words] : c.constants)
    out.push_back(
        differs("constants_" + type, "cloth's " + type + " springs", "take " + *words.begin()));
}

}  // namespace

void designCloth(std::vector<Designed>& out) {
  for (int k = 0; k < 2; ++k) out.push_back(designed("t4.cloth", ClothRequest{clothSpec(k)}));
}

std::vector<Finding> measureCloth(const Transcript& t) {
  ClothCount c;
  std::vector<Finding> out;
  std::set<std::string> said;
  for (const auto& x : answersTo<ClothRequest>(t, "t4.cloth")) {
    const ClothResult ref = reference::referenceCloth(x.request.spec);
    if (x.result.particles.size() <= harness::clothPrelude().particles.size()) continue;  // a stub
    if (const std::optional<Finding> f = particlesDiffer(x.result, ref, x.request.spec)) {
      if (said.insert("particles").second) out.push_back(*f);
      continue;
    }
    if (numberedFromZero(x.result, ref)) {
      if (said.insert("base").second)
        out.push_back(differs("base", "cloth's particle numbers",
                              "start from 0, not from base (the 3 particles the system held "
                              "before): every spring's ends are 3 lower"));
      continue;
    }
    countSprings(x.result, ref, x.request.spec, c);
    const std::string pins = pinnedPlaces(x.result, x.request.spec);
    const std::string physics = pinnedPlaces(ref, x.request.spec);
    if (pins != physics && said.insert("pins").second)
      out.push_back(
          differs("pins", "cloth's pins",
                  "are " + pins + " where the slide pins " + physics + " (the top corners)"));
  }
  addCounts(c, out);
  return out;
}

}  // namespace a6::grader::measured
