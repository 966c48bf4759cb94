# a6_grade, the command: main.cpp reads the command line, grading/ runs the stages in order,
# checks/ runs the physics suite (a6_suite: the test objects, no student code) and the
# golden-image checks (a6_golden_checks) against the probe, build/startup.cpp makes sure the
# probe starts. It links the grader's libraries, never a6_framework or a student object: student
# code only ever runs in the probe.
find_package(CLI11 REQUIRED)
find_package(GTest 1.11 REQUIRED)
if(NOT TARGET a6_suite OR NOT TARGET a6_golden_checks)
  message(STATUS "grader: no a6_grade without the checks it runs (A6_BUILD_TESTS=ON builds them)")
  return()
endif()

# The stages (everything but the command line), also linked by the tests' graders of a wrong
# version or an alternative whose code is linked in (tests/grader/linked_grade_main.cpp).
set(a6_grading_sources
  ${CMAKE_CURRENT_SOURCE_DIR}/grading/grading.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/checks/checks.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/checks/collector.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/checks/budgeted_student.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/checks/recording_student.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/checks/runs.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/checks/divergence.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/build/startup.cpp)
add_library(a6_grading OBJECT ${a6_grading_sources})
a6_bundled(a6_grading 4 ${a6_grading_sources})  # in two bundles (cmake/A6FastBuild.cmake)
target_include_directories(a6_grading PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(a6_grading PUBLIC a6_suite a6_golden_checks a6_report a6_rubric a6_intake
                                        a6_build a6_probe_client a6_mistakes
                                        a6_replay_view GTest::gtest)
# The reference force models the probe of tasks 3, 5 and 7 asks for (they stay in a6_grade).
target_compile_definitions(a6_grading PRIVATE A6_FORCE_MODELS="${A6_FORCE_MODELS}")

add_executable(a6_grade ${CMAKE_CURRENT_SOURCE_DIR}/main.cpp)
# (An object library's objects go only to what links it directly: the checks' too.)
target_link_libraries(a6_grade PRIVATE a6_grading a6_suite a6_golden_checks CLI11::CLI11)
a6_configured_path(a6_grade rubric "${A6_DEFAULT_RUBRIC}")
add_dependencies(a6_grade a6_grader_kit)  # grading builds against the kit
