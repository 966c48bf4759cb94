// a6_batch's command line: the options, read, and the paths, rubric and output folder they name,
// checked before any grading. Takes argv; gives the Options, or why the batch cannot start.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "common/limits.h"

namespace a6::grader::batch {

struct Options {
  std::string input;
  std::string out;
  std::string layout;
  std::string grader;
  std::string rubric;
  std::string kit;
  std::optional<std::uint64_t> seed;
  std::optional<double> timeBudget;
  int jobs = 0;
  double timeout = kBatchTimeout;
  bool force = false;
  bool keepWork = false;
  bool similarity = false;
  std::string starter;  ///< the starter files the similarity discounts (default: the build's)
};

/// Reads the command line into `options`; an exit status when the program ends here (--help,
/// or a command line it refuses).
std::optional<int> parseCommandLine(int argc, char** argv, Options& options);
/// The input folder, the output folder (created) and the grader, checked; why not, or "".
std::string checkPaths(const Options& options, std::filesystem::path& input,
                       std::filesystem::path& out, std::filesystem::path& grader);
/// A rubric that cannot be used would fail every grading: said now, before any. Why, or "".
std::string checkRubric(const Options& options, const std::filesystem::path& grader);
/// One batch at a time per output folder (a second would grade the same students at once): the
/// lock is held until the process ends. Why not, or "".
std::string lockOutput(const std::filesystem::path& out);
/// What else decides a grade, for the fingerprints: a change regrades.
std::string decidingOptions(const Options& options);

}  // namespace a6::grader::batch
