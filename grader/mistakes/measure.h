// Diagnosis by measurement (grader/mistakes/library/measured/, graders' material): inputs
// designed to take each task's functions apart, asked of the student's code after every check
// (checks/runs.h: askDesigned), and the answers fitted to the slide's parts (measured/fit.h). A
// part that differs is named with how it differs where one fit explains every answer; otherwise
// the diagnosis says what was measured. A task none of whose measured parts differs gets nothing
// (its checks' hints stand).
//
// Takes the answers to the designed inputs and the tasks whose physics checks failed; gives at
// most one NamedMistake per such task. Without the library (a student release) nothing is
// designed and nothing diagnosed.
#pragma once

#include <set>
#include <vector>

#include "checks/transcript.h"
#include "mistakes/named.h"

namespace a6::grader {

/// The inputs the diagnosis measures on, each labelled with what it measures.
const std::vector<Designed>& designedInputs();

/// The diagnosis of each failing task that the designed inputs measure, in task order.
std::vector<NamedMistake> diagnose(const Transcript& measured, const std::set<int>& failingTasks);

/// One mistake per task: the catalogue's (mistakes.h: its exact text, fitted on every public
/// check's answer) where it named one, else the diagnosis's.
std::vector<NamedMistake> combine(const std::vector<NamedMistake>& catalogue,
                                  const std::vector<NamedMistake>& diagnosed);

}  // namespace a6::grader
