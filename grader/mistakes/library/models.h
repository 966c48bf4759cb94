// The library of known mistakes, one file per task, each model written from a wrong version
// under tests/wrong/ (its id is that folder's name). Graders' material: never in a student
// release (grader/release/export-student.sh leaves this folder out).
//
// To add one: write what the mistaken code answers for the requests its task's public checks
// make (beside the reference's answer, in the task's file), give it the wrong version's name and
// one sentence for the student, and add the wrong version to tests/wrong/ with
// "mistake: <id>" in its EXPECT file (docs/instructor.md, "The mistake library").
#pragma once

#include <vector>

#include "mistakes/mistakes.h"

namespace a6::grader::mistakes {

std::vector<MistakeModel> task1Mistakes();  // spring force
std::vector<MistakeModel> task2Mistakes();  // forces
std::vector<MistakeModel> task3Mistakes();  // time stepping
std::vector<MistakeModel> task4Mistakes();  // cloth builder
std::vector<MistakeModel> task5Mistakes();  // particle system
std::vector<MistakeModel> task6Mistakes();  // Box2D joints
std::vector<MistakeModel> task7Mistakes();  // implicit step
/// The spring force (task 1) and springJacobians (task 7), named part by part (parts.cpp).
std::vector<MistakeModel> partByPartMistakes();

}  // namespace a6::grader::mistakes
