// A file's bytes, all of them: "" when it cannot be read. For files the grader or the TA wrote
// (a log, a rubric, a marker), never for a submission's, whose size is not bounded.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace a6::grader {

inline std::string readAll(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace a6::grader
