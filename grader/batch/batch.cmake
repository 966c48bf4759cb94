# Grading a folder of submissions (batch/: a6_batch). It runs a6_grade per submission, so it
# links none of the grading: a6_batch_core (layouts, outcomes, gradebook).
find_package(CLI11 REQUIRED)

add_library(a6_batch_core STATIC ${CMAKE_CURRENT_SOURCE_DIR}/batch/layouts.cpp
                                 ${CMAKE_CURRENT_SOURCE_DIR}/batch/batch.cpp)
target_include_directories(a6_batch_core PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
find_package(PkgConfig REQUIRED)
pkg_check_modules(YAMLCPP REQUIRED IMPORTED_TARGET yaml-cpp>=0.7)  # submission_metadata.yml
target_link_libraries(a6_batch_core PRIVATE nlohmann_json::nlohmann_json PkgConfig::YAMLCPP)

add_executable(a6_batch ${CMAKE_CURRENT_SOURCE_DIR}/batch/batch_main.cpp
                        ${CMAKE_CURRENT_SOURCE_DIR}/batch/command_line.cpp
                        ${CMAKE_CURRENT_SOURCE_DIR}/batch/progress.cpp)
target_link_libraries(a6_batch PRIVATE a6_batch_core a6_insights_core a6_process
                                       CLI11::CLI11)
# The default rubric, as a6_grade reads it: part of every submission's fingerprint, so that a
# changed rubric regrades.
a6_configured_path(a6_batch rubric "${A6_DEFAULT_RUBRIC}")
a6_configured_path(a6_batch starter "${PROJECT_SOURCE_DIR}/starter")
if(TARGET a6_grade)
  add_dependencies(a6_batch a6_grade)  # found beside a6_batch
endif()
