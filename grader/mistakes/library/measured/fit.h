// Diagnosis by measurement: one part of a slide's law (the spring force's elastic term, gravity,
// dfdx's part along the spring...) measured on designed inputs, and what it measured fitted to
// the slide's law, so that a mistake nobody listed is still described in the slide's words.
//
// Takes a part's samples: at each designed input the values of the law's variables, the physics'
// value, the student's, and the slide's terms (whose sum, each with its weight, is the physics').
// Gives whether the part is right, how it differs where one fit explains every sample, or else
// what was measured. Two fits are tried:
//   - the ratio: the student's value along the physics' direction, divided by the physics', as a
//     constant times a power of each variable ("2 times the physics' size", "times kd/ks",
//     "times l");
//   - the terms: the student's value as a weighted sum of the slide's terms and their known
//     alternatives ("leaves out ks l0 e", "counts m g twice", "uses k_d d n where the slide has
//     k_r d n").
// A fit explains a part only when it predicts every sample within kFitTolerance; the simpler of
// the fits that do wins.
#pragma once

#include <string>
#include <vector>

#include "a6/particle.h"

namespace a6::grader::measured {

/// How close a fit's prediction must come to each answer, relative to the answer's size: far
/// looser than float intermediates (1e-7), far tighter than any mistake that matters.
constexpr double kFitTolerance = 1e-4;

/// A variable of a part's law, as the slide names it.
struct Variable {
  std::string name;          ///< "ks", "l", "|v|"
  bool coefficient = false;  ///< a constant the student passes on (ks, kd, k_d, k_r, b)
  double power = 0;          ///< its power in the physics' formula where it is a factor (m g: 1)
};

/// A term of the slide's formula, or an alternative a student may write in its place.
struct Term {
  std::string name;   ///< "ks l0 e", "k_d d n (every half-plane)"
  double weight = 1;  ///< its weight in the physics (0 for an alternative)
  int replaces = -1;  ///< an alternative: the index of the term it stands for, else -1
};

/// One designed input of a part.
struct Sample {
  std::vector<double> values;  ///< each Variable's value here (positive)
  Vec2 physics = Vec2::Zero(), yours = Vec2::Zero();
  std::vector<Vec2> terms;  ///< each Term's value here
  std::string where;        ///< the input, in the slide's words: "l = 2.6, l0 = 1.3"
  /// The size an answer here is measured against where the physics' and the terms are small (a
  /// pinned particle's, a Jacobian's mixed part): 0 takes theirs.
  double scale = 0;
};

/// A part of a law and its measurements.
struct Part {
  std::string tag;      ///< for the diagnosis's id: "elastic"
  std::string name;     ///< "spring force's elastic term"
  std::string formula;  ///< the slide's: "-ks (l - l0) e"
  std::string unit;     ///< of its values: "N"
  bool scalar = false;  ///< its values are numbers (in x; y is 0), not vectors
  std::vector<Variable> variables;
  std::vector<Term> terms;
  std::vector<Sample> samples;
};

enum class Verdict {
  Right,        ///< every sample within tolerance of the physics
  Differs,      ///< one fit explains every sample: `how` says how it differs
  Unexplained,  ///< it differs, and no fit explains it: `measured` says what was measured
  Unmeasured,   ///< no sample was answered
};

struct Finding {
  Verdict verdict = Verdict::Unmeasured;
  std::string tag;       ///< Part::tag
  std::string part;      ///< Part::name
  std::string key;       ///< a short tag of how it differs ("factor", "terms", "ratio"), for ids
  std::string how;       ///< "is 2 times the physics' size"
  std::string measured;  ///< "at l = 2.6, l0 = 1.3: yours (1.2, 0.3) N, the physics' (...)"
  bool zero = false;     ///< every answer measured was zero (a starter's stub answers so)
};

/// The part measured and fitted.
Finding measure(const Part& part);

/// A number for a sentence: 3 significant digits, no trailing zeros ("2", "0.5", "-1.25").
std::string number(double x);

/// A vector for a sentence: "(1.2, -0.5)".
std::string vector(const Vec2& v);

}  // namespace a6::grader::measured
