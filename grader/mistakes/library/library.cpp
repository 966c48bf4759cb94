// The library of known mistakes: every task's models, in task order.
#include "mistakes/library/models.h"

namespace a6::grader {

const std::vector<MistakeModel>& mistakeLibrary() {
  static const std::vector<MistakeModel> all = [] {
    std::vector<MistakeModel> models;
    for (auto part : {mistakes::task1Mistakes, mistakes::task2Mistakes, mistakes::task3Mistakes,
                      mistakes::task4Mistakes, mistakes::task5Mistakes, mistakes::task6Mistakes,
                      mistakes::task7Mistakes, mistakes::partByPartMistakes}) {
      for (MistakeModel& m : part()) models.push_back(std::move(m));
    }
    return models;
  }();
  return all;
}

}  // namespace a6::grader
