// Each task's designed inputs and its measured parts (fit.h), for the diagnosis (measure.h).
// A task's `design` appends its labelled requests; its `measure` reads their answers back by
// label and gives one Finding per part, in the slide's order.
#pragma once

#include <string>
#include <vector>

#include "checks/transcript.h"
#include "mistakes/library/measured/fit.h"

namespace a6::grader::measured {

void designSpring(std::vector<Designed>& out);                 // tasks 1 and 7
std::vector<Finding> measureSpringForce(const Transcript& t);  // task 1
std::vector<Finding> measureJacobians(const Transcript& t);    // task 7
void designForces(std::vector<Designed>& out);                 // task 2
std::vector<Finding> measureForces(const Transcript& t);
void designStepping(std::vector<Designed>& out);  // task 3
std::vector<Finding> measureStepping(const Transcript& t);
void designCloth(std::vector<Designed>& out);  // task 4
std::vector<Finding> measureCloth(const Transcript& t);
void designParticles(std::vector<Designed>& out);  // task 5
std::vector<Finding> measureParticles(const Transcript& t);
void designJoints(std::vector<Designed>& out);  // task 6
std::vector<Finding> measureJoints(const Transcript& t);
void designImplicit(std::vector<Designed>& out);  // task 7's step
std::vector<Finding> measureImplicit(const Transcript& t);

/// The position update x += v dt with the new v (tasks 3, 5 and 7): Δx as the old velocity's
/// v dt and the step's own Δv dt.
Part positionPart();

/// The answers to the requests of kind R labelled `label`, in order, each with its request.
template <class R>
std::vector<ExchangeOf<R>> answersTo(const Transcript& t, const std::string& label) {
  std::vector<ExchangeOf<R>> out;
  for (const ExchangeOf<R>& x : t.of<R>()) {
    if (x.check == label) out.push_back(x);
  }
  return out;
}

/// A labelled request of kind R.
template <class R>
Designed designed(std::string label, const R& request) {
  return {std::move(label), harness::Request(std::in_place_index<harness::kKindOf<R>>, request)};
}

}  // namespace a6::grader::measured
