// How a model's answers are set beside the student's: closeness of numbers (NaN is like NaN),
// and one Likeness per request from the reference's, the mistake's and the student's answers.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "mistakes/mistakes.h"

namespace a6::grader::mistakes {

/// Relative closeness: far looser than any summation order or float intermediates make (about
/// 1e-7), far tighter than any mistake of the library changes an answer.
constexpr double kTolerance = 1e-5;

/// a and b within kTolerance of `scale` (NaN is close only to NaN, infinity only to itself).
inline bool near(double a, double b, double scale) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= kTolerance * scale + 1e-12;
}
inline bool near(double a, double b) { return near(a, b, std::max(std::abs(a), std::abs(b))); }
inline bool near(const Vec2& a, const Vec2& b, double scale) {
  return near(a.x(), b.x(), scale) && near(a.y(), b.y(), scale);
}
inline bool near(const Vec2& a, const Vec2& b) {
  const double scale = std::max(std::max(std::abs(a.x()), std::abs(a.y())),
                                std::max(std::abs(b.x()), std::abs(b.y())));
  return near(a, b, scale);
}

/// Two runs' recorded positions and velocities, each within kTolerance of b's largest value.
inline bool sameRun(const harness::SimulateResult& a, const harness::SimulateResult& b) {
  if (a.recordedFrames != b.recordedFrames || a.states.size() != b.states.size()) return false;
  double scale = 0;
  for (const auto& state : b.states) {
    for (const Particle& p : state) scale = std::max({scale, p.x.norm(), p.v.norm()});
  }
  for (std::size_t k = 0; k < a.states.size(); ++k) {
    if (a.states[k].size() != b.states[k].size()) return false;
    for (std::size_t i = 0; i < a.states[k].size(); ++i) {
      const Particle &p = a.states[k][i], &q = b.states[k][i];
      if (!near(p.x, q.x, scale) || !near(p.v, q.v, scale)) return false;
    }
  }
  return true;
}

/// The likeness of one answer: the mistake's and the reference's answers decide whether the
/// request tells anything, then the student's is set beside each. Where the mistake answers as
/// the reference does, a student who answers otherwise made some other mistake: like neither.
template <class Result, class Same>
Likeness likeness(const Result& student, const Result& reference, const Result& mistaken,
                  Same same) {
  if (same(reference, mistaken)) {
    return same(student, reference) ? Likeness::Uninformative : Likeness::Neither;
  }
  if (same(student, mistaken)) return Likeness::Mistake;
  if (same(student, reference)) return Likeness::Reference;
  return Likeness::Neither;
}

/// One likeness per exchange that both answers can be given for. `reference` and `mistaken`
/// map a request to std::optional<Result> (empty: the model cannot answer that request).
template <class Exchanges, class Reference, class Mistaken, class Same>
std::vector<Likeness> judgeEach(const Exchanges& exchanges, Reference reference, Mistaken mistaken,
                                Same same) {
  std::vector<Likeness> out;
  for (const auto& x : exchanges) {
    const auto r = reference(x.request), m = mistaken(x.request);
    if (r && m) out.push_back(likeness(x.result, *r, *m, same));
  }
  return out;
}

/// The catalogue models of task `task` written from one function answer(request, flaw) (a
/// std::optional, empty where it cannot answer): gives model(id, flaw, text), judged on every
/// request of kind R, the flaw's answer beside the reference's, answer(request, Flaw{}) (Flaw{}:
/// each Flaw's first value, None, or false).
template <class R, class Flaw, class Answer, class Same>
auto flawModels(int task, Answer answer, Same same) {
  return [task, answer, same](const char* id, Flaw flaw, const char* text) {
    auto judge = [answer, same, flaw](const Transcript& t) {
      return judgeEach(
          t.of<R>(), [answer](const R& r) { return answer(r, Flaw{}); },
          [answer, flaw](const R& r) { return answer(r, flaw); }, same);
    };
    return MistakeModel{id, task, text, judge};
  };
}

/// Whether every answer to the requests of kind R is zero (`zero` says so of one): a stub's,
/// which is named nothing (however its zeros happen to fit a wrong form on the inputs the checks
/// used).
template <class R, class Zero>
bool allZero(const Transcript& t, Zero zero) {
  for (const auto& x : t.of<R>()) {
    if (!zero(x.result)) return false;
  }
  return true;
}

/// A likeness from what the student's answer shows directly (for mistakes recognised by a
/// property of the answer: a joint's limit left off, a pointer left set).
inline Likeness shows(bool likeMistake, bool likeReference) {
  if (likeMistake && !likeReference) return Likeness::Mistake;
  if (likeReference && !likeMistake) return Likeness::Reference;
  return Likeness::Neither;
}

}  // namespace a6::grader::mistakes
