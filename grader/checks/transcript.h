// What the student's code answered to the public checks of tasks 1 to 7 (not the hidden ones,
// whose inputs are random, nor the images): each request beside its answer, in the order the
// checks asked. The checks stage gives it (RecordingStudent); the mistakes stage compares it
// with the known mistakes (grader/mistakes/), and the replays draw from it (grader/replay/).
// Only requests that ran to the end are kept.
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "harness/student_code.h"

namespace a6::grader {

/// One request and the student's answer to it.
struct Exchange {
  std::string check;  ///< the check that asked, "Task1Spring.StretchedAlongX"
  harness::Request request;
  harness::Answer answer;  ///< at the request's index
};

/// A request the diagnosis designed (grader/mistakes/measure.h), asked after every check has been
/// collected; `label` says what it measures ("t1.elastic").
struct Designed {
  std::string label;
  harness::Request request;
};

/// One exchange of request kind R, typed (a view into the transcript).
template <class R>
struct ExchangeOf {
  const std::string& check;
  const R& request;
  const typename R::Result& result;
};

struct Transcript {
  std::vector<Exchange> exchanges;  ///< in the order the checks asked

  template <class R>
  void add(std::string check, const R& request, typename R::Result result) {
    exchanges.push_back({std::move(check),
                         harness::Request(std::in_place_index<harness::kKindOf<R>>, request),
                         harness::answerTo<R>(std::move(result))});
  }
  /// The exchanges of kind R, in order.
  template <class R>
  std::vector<ExchangeOf<R>> of() const {
    std::vector<ExchangeOf<R>> out;
    for (const Exchange& x : exchanges) {
      if (x.request.index() != harness::kKindOf<R>) continue;
      out.push_back({x.check, std::get<harness::kKindOf<R>>(x.request),
                     std::get<harness::kKindOf<R>>(x.answer)});
    }
    return out;
  }
};

}  // namespace a6::grader
