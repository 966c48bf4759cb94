#include "mistakes/library/measured/fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace a6::grader::measured {
namespace {

// A fit's result: whether it explains every sample, how far it is from the physics (how many of
// its parameters differ), and its words.
struct Fit {
  bool explains = false;
  int deviations = 0;
  std::string key, how;
};

// |v|, or 0 where v is not finite or its size overflows: a hostile answer sets no scale.
double sizeOf(const Vec2& v) {
  const double n = v.norm();
  return std::isfinite(n) ? n : 0;
}

double sizeOf(const Part& p) {
  double size = 0;
  for (const Sample& s : p.samples) size = std::max({size, sizeOf(s.physics), sizeOf(s.yours)});
  return size;
}

// The size of a sample's answers: the largest of the physics', the student's, the terms' sum of
// sizes and its own scale, so that a rounding where the physics' is zero stays a rounding.
double scaleOf(const Sample& s) {
  double terms = 0;
  for (const Vec2& t : s.terms) terms += sizeOf(t);
  return std::max({sizeOf(s.physics), sizeOf(s.yours), terms, s.scale});
}

// Whether a is b at the sample's scale (never where either is not finite).
bool close(const Vec2& a, const Vec2& b, const Sample& s, double floor) {
  const double d = (a - b).norm();
  return std::isfinite(d) && d <= kFitTolerance * scaleOf(s) + floor;
}

// x rounded to the nearest half when it is that close (an exponent, a weight), else x.
double snapped(double x, double within) {
  const double half = std::round(2 * x) / 2;
  return std::abs(x - half) <= within ? half : x;
}

// "ks", "l²", "l^1.5": a variable to a power (the power's size).
std::string power(const std::string& name, double p) {
  const double a = std::abs(p);
  if (a == 1) return name;
  if (a == 2) return name + "²";
  if (a == 3) return name + "³";
  return name + "^" + number(a);
}

// "m", "1/m", "m²", "1/m²": a variable to a power, its sign shown (a factor's own words).
std::string signedPower(const std::string& name, double p) {
  return p < 0 ? "1/" + power(name, p) : power(name, p);
}

// The factor C · Π v^p as the slide would write it: "2", "kd/ks", "l", "1/m".
std::string factorWords(double c, const std::vector<Variable>& vars, const std::vector<double>& p) {
  std::string top, bottom;
  for (std::size_t k = 0; k < vars.size(); ++k) {
    if (p[k] == 0) continue;
    std::string& side = p[k] > 0 ? top : bottom;
    side += (side.empty() ? "" : " ") + power(vars[k].name, p[k]);
  }
  std::string out = c == 1 && !top.empty() ? "" : c == -1 && !top.empty() ? "-" : number(c);
  if (!top.empty()) out += (out.empty() || out == "-" ? "" : " ") + top;
  if (top.empty() && !bottom.empty() && c == 1) out = "1";
  if (!bottom.empty())
    out += "/" + (bottom.find(' ') == std::string::npos ? bottom : "(" + bottom + ")");
  return out;
}

// The ratio fit's words: a constant factor, a coefficient in place of another, a variable the
// physics' value does not depend on this way.
std::string ratioWords(const Part& part, double c, const std::vector<double>& p) {
  int up = -1, down = -1, others = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (p[k] == 1 && part.variables[k].coefficient)
      up = static_cast<int>(k);
    else if (p[k] == -1 && part.variables[k].coefficient)
      down = static_cast<int>(k);
    else if (p[k] != 0)
      ++others;
  }
  if (up < 0 && down < 0 && others == 0) {
    if (c == -1) return "has the wrong sign (-1 times the physics')";
    if (c == 2) return "is counted twice (2 times the physics' size)";
    return "is " + number(c) + " times the physics' size";
  }
  std::string how =
      "is the physics' " + part.formula + " times " + factorWords(c, part.variables, p);
  if (up >= 0 && down >= 0 && others == 0 && std::abs(c) == 1) {
    how += ": it uses " + part.variables[up].name + " where the slide has " +
           part.variables[down].name + (c == -1 ? ", and has the wrong sign" : "");
  } else {
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Variable& v = part.variables[k];
      if (p[k] == 0 || (v.coefficient && v.power == 0)) continue;
      if (p[k] == -v.power) {
        how += ", so it leaves out the factor " + signedPower(v.name, v.power);
      } else if (v.power != 0) {
        how += ", so it goes with " + signedPower(v.name, v.power + p[k]) +
               " where the physics' goes with " + signedPower(v.name, v.power);
      } else {
        how += std::string(", so it ") + (p[k] > 0 ? "grows" : "shrinks") + " with " +
               power(v.name, p[k]) + " where the physics' does not";
      }
    }
  }
  return how;
}

// The exponents and the constant of log|ratio| = c + Σ p log v, fitted to the rows of `a` (a
// first column of ones, then each variable's log) and `b`; a variable that does not vary keeps
// exponent 0. Explains when every exponent is a whole or half number and the fit meets every row.
Fit ratioSolved(const Part& part, const Eigen::MatrixXd& a, const Eigen::VectorXd& b, double sign) {
  std::vector<int> varying;
  for (int v = 1; v < a.cols(); ++v) {
    if (a.col(v).maxCoeff() - a.col(v).minCoeff() > 1e-9) varying.push_back(v);
  }
  Eigen::MatrixXd reduced(a.rows(), varying.size() + 1);
  reduced.col(0) = a.col(0);
  for (std::size_t j = 0; j < varying.size(); ++j) reduced.col(j + 1) = a.col(varying[j]);
  const auto qr = reduced.colPivHouseholderQr();
  if (qr.rank() < reduced.cols()) return {};
  Eigen::VectorXd x = qr.solve(b);
  std::vector<double> p(part.variables.size(), 0);
  for (std::size_t j = 0; j < varying.size(); ++j) {
    const double e = snapped(x(j + 1), 0.05);
    if (e != std::round(2 * e) / 2) return {};
    p[varying[j] - 1] = e;
  }
  Eigen::VectorXd exponents = Eigen::VectorXd::Zero(a.cols());
  for (std::size_t v = 0; v < p.size(); ++v) exponents(v + 1) = p[v];
  const double c0 = (b - a * exponents).mean();
  exponents(0) = c0;
  if (((a * exponents - b).array().abs() > 2 * kFitTolerance).any()) return {};
  double c = sign * std::exp(c0);
  if (std::abs(c - std::round(c)) <= kFitTolerance * std::abs(c)) c = std::round(c);
  Fit fit{true, c == 1 ? 0 : 1, "ratio", ""};
  int coefficientsUp = 0;
  for (std::size_t v = 0; v < p.size(); ++v) {
    if (p[v] == 0) continue;
    if (part.variables[v].coefficient && p[v] == 1 && coefficientsUp++ == 0) continue;
    ++fit.deviations;  // a coefficient in place of another counts once
  }
  if (fit.deviations == 0) return {};  // the physics itself: not a difference
  if (std::all_of(p.begin(), p.end(), [](double e) { return e == 0; })) fit.key = "factor";
  fit.how = ratioWords(part, c, p);
  return fit;
}

// The ratio fit (see fit.h), on the samples where the physics' value is not zero; where it is,
// the student's must be zero too.
Fit ratioFit(const Part& part, double floor) {
  std::vector<const Sample*> rows;
  for (const Sample& s : part.samples) {
    if (s.physics.norm() > floor)
      rows.push_back(&s);
    else if (s.yours.norm() > floor)
      return {};
  }
  const std::size_t k = part.variables.size();
  if (rows.size() < k + 2) return {};
  Eigen::MatrixXd a(rows.size(), k + 1);
  Eigen::VectorXd b(rows.size());
  double sign = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Vec2 dir = rows[i]->physics.normalized(), across(-dir.y(), dir.x());
    const double along = rows[i]->yours.dot(dir) / rows[i]->physics.norm();
    if (std::abs(rows[i]->yours.dot(across)) > kFitTolerance * rows[i]->yours.norm() + floor ||
        !(std::abs(along) > 1e-9) || (sign != 0 && along * sign < 0))
      return {};
    sign = along > 0 ? 1 : -1;
    b(i) = std::log(std::abs(along));
    a(i, 0) = 1;
    for (std::size_t v = 0; v < k; ++v) a(i, v + 1) = std::log(rows[i]->values[v]);
  }
  return ratioSolved(part, a, b, sign);
}

// The term fit's words: each weight that is not the physics'.
std::string termWords(const Part& part, const std::vector<double>& w) {
  std::vector<std::string> said;
  std::vector<bool> done(w.size(), false);
  for (std::size_t j = 0; j < w.size(); ++j) {  // an alternative in its term's place
    const int r = part.terms[j].replaces;
    if (r >= 0 && w[j] == 1 && w[r] == 0) {
      said.push_back("uses " + part.terms[j].name + " where the slide has " + part.terms[r].name);
      done[j] = done[r] = true;
    }
  }
  for (std::size_t j = 0; j < w.size(); ++j) {
    const Term& t = part.terms[j];
    if (done[j] || w[j] == t.weight) continue;
    if (t.weight == 0)
      said.push_back("adds " + (w[j] == 1 ? "" : number(w[j]) + " times ") + t.name +
                     ", which the slide does not have");
    else if (w[j] == 0)
      said.push_back("leaves out " + t.name);
    else if (w[j] == 2 * t.weight)
      said.push_back("counts " + t.name + " twice");
    else if (w[j] == -t.weight)
      said.push_back("has " + t.name + " with the wrong sign");
    else
      said.push_back("takes " + t.name + " " + number(w[j] / t.weight) + " times");
  }
  std::string out;
  for (const std::string& s : said) out += (out.empty() ? "" : "; ") + s;
  return out;
}

// The term fit (see fit.h): the student's values as a weighted sum of the terms. A term that is
// zero at every sample keeps the physics' weight.
Fit termFit(const Part& part, double floor) {
  const std::size_t n = part.terms.size(), rows = 2 * part.samples.size();
  if (n == 0 || rows < n + 2) return {};
  Eigen::MatrixXd a(rows, n);
  Eigen::VectorXd b(rows);
  for (std::size_t i = 0; i < part.samples.size(); ++i) {
    const Sample& s = part.samples[i];
    for (std::size_t j = 0; j < n; ++j) a.block<2, 1>(2 * i, j) = s.terms[j];
    b.segment<2>(2 * i) = s.yours;
  }
  std::vector<double> w(n);
  std::vector<int> free;
  for (std::size_t j = 0; j < n; ++j) {
    w[j] = part.terms[j].weight;
    if (a.col(j).norm() > floor)
      free.push_back(static_cast<int>(j));
    else
      b -= w[j] * a.col(j);
  }
  Eigen::MatrixXd reduced(rows, free.size());
  for (std::size_t j = 0; j < free.size(); ++j) reduced.col(j) = a.col(free[j]);
  const auto qr = reduced.colPivHouseholderQr();
  if (free.empty() || qr.rank() < reduced.cols()) return {};
  const Eigen::VectorXd x = qr.solve(b);
  for (std::size_t j = 0; j < free.size(); ++j) w[free[j]] = snapped(x(j), 1e-3);
  Fit fit{true, 0, "terms", ""};
  for (std::size_t i = 0; i < part.samples.size(); ++i) {
    Vec2 predicted = Vec2::Zero();
    for (std::size_t j = 0; j < n; ++j) predicted += w[j] * part.samples[i].terms[j];
    if (!close(predicted, part.samples[i].yours, part.samples[i], floor)) return {};
  }
  for (std::size_t j = 0; j < n; ++j) fit.deviations += w[j] != part.terms[j].weight;
  if (fit.deviations == 0) return {};
  fit.how = termWords(part, w);
  return fit;
}

// What was measured, plainly: the samples that differ, most first (at most three).
std::string measuredWords(const Part& part, double floor) {
  std::vector<const Sample*> differ;
  for (const Sample& s : part.samples) {
    if (!close(s.yours, s.physics, s, floor)) differ.push_back(&s);
  }
  const auto off = [](const Sample* s) {  // a NaN sorts first, as the largest
    const double d = (s->yours - s->physics).norm();
    return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
  };
  std::stable_sort(differ.begin(), differ.end(),
                   [&off](const Sample* x, const Sample* y) { return off(x) > off(y); });
  std::string out;
  for (std::size_t i = 0; i < differ.size() && i < 3; ++i) {
    const Sample& s = *differ[i];
    const auto show = [&part](const Vec2& v) {
      return (part.scalar ? number(v.x()) : vector(v)) + (part.unit.empty() ? "" : " " + part.unit);
    };
    out += (out.empty() ? "at " : "; at ") + s.where + ": yours " + show(s.yours) +
           ", the physics' " + show(s.physics);
  }
  return out;
}

}  // namespace

Finding measure(const Part& part) {
  Finding f;
  f.tag = part.tag;
  f.part = part.name;
  if (part.samples.empty()) return f;
  const double floor = 1e-9 * std::max(1.0, sizeOf(part));
  bool right = true, finite = true, physicsZero = true;
  bool& zero = f.zero = true;
  for (const Sample& s : part.samples) {
    finite = finite && s.yours.allFinite();
    right = right && close(s.yours, s.physics, s, floor);
    zero = zero && s.yours.norm() <= floor;
    physicsZero = physicsZero && s.physics.norm() <= floor;
  }
  f.measured = measuredWords(part, floor);
  if (right) return f.verdict = Verdict::Right, f;
  f.verdict = Verdict::Differs;
  if (finite && zero && !physicsZero)
    return f.key = "missing", f.how = "is missing (0 at every input)", f;
  const Fit ratio = finite ? ratioFit(part, floor) : Fit{};
  const Fit terms = finite ? termFit(part, floor) : Fit{};
  const Fit* best = nullptr;
  for (const Fit* fit : {&ratio, &terms}) {
    if (fit->explains && (best == nullptr || fit->deviations < best->deviations)) best = fit;
  }
  if (best == nullptr) return f.verdict = Verdict::Unexplained, f;
  f.key = best->key;
  f.how = best->how;
  return f;
}

std::string number(double x) {
  if (std::abs(x) < 1e-12) x = 0;  // a rounding's leftover, not a value
  char text[32];
  if (std::abs(x) >= 1e3 && std::abs(x) < 1e7) {  // "1250", not "1.25e+03"
    std::snprintf(text, sizeof text, "%.0f", x);
    return text;
  }
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

std::string vector(const Vec2& v) { return "(" + number(v.x()) + ", " + number(v.y()) + ")"; }

}  // namespace a6::grader::measured
