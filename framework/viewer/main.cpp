// a6_viewer: the interactive viewer (see docs/viewer.md). Built with the configured student
// files (-DA6_STUDENT=...), so students watch their own code run.
#include <cstdio>
#include <string>
#include <vector>

#include "scenes/scene.h"
#include "viewer/viewer.h"
#include "viewer/viewer_options.h"

int main(int argc, char** argv) {
  using namespace a6;
  const std::string program = argc > 0 ? argv[0] : "a6_viewer";
  const viewer::ParseResult parsed =
      viewer::parseOptions(std::vector<std::string>(argv + 1, argv + argc));
  if (!parsed) {
    std::fprintf(stderr, "a6_viewer: %s\n\n%s", parsed.error.c_str(),
                 viewer::usage(program).c_str());
    return 2;
  }
  const viewer::Options& options = parsed.options;
  if (options.help) {
    std::printf("%s", viewer::usage(program).c_str());
    return 0;
  }
  if (options.list) {
    for (const std::string& name : sceneNames()) {
      const SceneInfo* info = sceneInfo(name);
      std::printf("%-18s task %d  %s\n", name.c_str(), info->task, info->title.c_str());
    }
    return 0;
  }
  if (sceneInfo(options.scene) == nullptr) {
    std::fprintf(stderr, "a6_viewer: unknown scene '%s'; the scenes are:\n", options.scene.c_str());
    for (const std::string& name : sceneNames()) std::fprintf(stderr, "  %s\n", name.c_str());
    return 2;
  }
  viewer::Viewer viewer(options);
  return viewer.run();
}
