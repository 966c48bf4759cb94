// What the grader's commands (a6_grade, a6_batch, a6_insights) share on their command lines.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>

namespace a6::grader {

/// `name` in the running program's folder (the build's, or the Gradescope package's), or `name`
/// itself when that folder cannot be known.
inline std::filesystem::path besideProgram(const std::string& name) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path(name) : self.parent_path() / name;
}

/// Reads the command line into `app`'s options: nothing when the command goes on, else its exit
/// status (0 after --help, 2 for a line it cannot read, which CLI11 explains on stderr).
inline std::optional<int> parseOrExit(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return std::nullopt;
}

}  // namespace a6::grader
