// The kit a submission's probe is built with: where it is, what it holds (build.h).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>
#include <vector>

#include "build/build.h"
#include "common/limits.h"
#include "harness/tasks.h"

namespace a6::paths {
extern const char kit_json[];  // BUILD/grader/kit.json (a6_configured_path)
}  // namespace a6::paths

namespace a6::grader {

namespace fs = std::filesystem;

fs::path defaultKitPath() { return paths::kit_json; }

Limits defaultCompileLimits() {
  Limits l;
  l.wallSeconds = kCompileSeconds;
  l.cpuSeconds = kCompileSeconds;
  l.memoryBytes = kCompileMemoryBytes;
  l.fileSizeBytes = std::size_t{64} << 20;
  l.processes = 8;
  l.outputBytes = std::size_t{64} << 10;
  return l;
}

Kit loadKit(const fs::path& kitJson) {
  Kit kit;
  const std::string rebuild = " (rebuild the grader: cmake --build BUILD --target a6_grader_kit)";
  std::ifstream in(kitJson);
  if (!in) {
    kit.error = "cannot read the grader kit " + kitJson.string() + rebuild;
    return kit;
  }
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    kit.compiler = j.at("compiler").get<std::string>();
    kit.compileFlags = j.at("compileFlags").get<std::vector<std::string>>();
    kit.probeMain = j.at("probeMain").get<std::vector<std::string>>();
    kit.modelsMain = j.value("modelsMain", std::vector<std::string>{});
    kit.linkInputs = j.at("linkInputs").get<std::vector<std::string>>();
    kit.starterObjects = j.at("starterObjects").get<std::string>();
    kit.knownObjects = j.value("knownObjects", std::string());
    kit.dir = j.at("dir").get<std::string>();
    for (const std::string& s : j.value("secrets", std::vector<std::string>{})) {
      kit.secrets.emplace_back(s);
    }
  } catch (const std::exception& e) {
    kit.error = "the grader kit " + kitJson.string() + " is malformed: " + e.what() + rebuild;
    return kit;
  }
  std::error_code ec;
  if (::access(kit.compiler.c_str(), X_OK) != 0) {
    kit.error = "the kit's compiler " + kit.compiler + " is not an executable" + rebuild;
    return kit;
  }
  if (kit.probeMain.empty() || kit.modelsMain.empty()) {
    kit.error = "the grader kit " + kitJson.string() +
                " names no probe main (the probe targets a6_probe_main, a6_probe_main_models and "
                "a6_probe_kit were not part of the build)" +
                rebuild;
    return kit;
  }
  std::vector<fs::path> needed;
  for (const std::string& file : kTaskFiles) {
    needed.push_back(kit.starterObjects / (fs::path(file).stem().string() + ".o"));
  }
  for (const std::string& input : kit.probeMain) needed.emplace_back(input);
  for (const std::string& input : kit.modelsMain) needed.emplace_back(input);
  for (const std::string& input : kit.linkInputs) {
    if (!input.empty() && input[0] == '/') needed.emplace_back(input);
  }
  for (const fs::path& file : needed) {
    if (!fs::is_regular_file(file, ec)) {
      kit.error = "the grader kit lacks " + file.string() + rebuild;
      return kit;
    }
  }
  return kit;
}

}  // namespace a6::grader
