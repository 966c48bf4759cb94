// A file's bytes, all of them: "" when it cannot be read, or when it holds more than `cap` bytes
// (nothing past the cap is kept). For files the grader or the TA wrote (a log, a rubric, a
// marker, a results.json), never for a submission's, whose size is not bounded.
#pragma once

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace a6::grader {

inline std::string readAll(const std::filesystem::path& file,
                           std::size_t cap = std::numeric_limits<std::size_t>::max()) {
  std::ifstream in(file, std::ios::binary);
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > cap) return "";
  }
  return text;
}

}  // namespace a6::grader
