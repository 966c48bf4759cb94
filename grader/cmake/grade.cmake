# a6_grade, the command (grader/main.cpp): helper "rubric_report". It links the physics suite
# (a6_suite: the test objects, no student code) and the grader's libraries, never a6_framework
# or a student object: student code only ever runs in the probe.
find_package(CLI11 REQUIRED)
find_package(GTest 1.11 REQUIRED)

if(TARGET a6_suite)
  add_executable(a6_grade ${CMAKE_CURRENT_SOURCE_DIR}/main.cpp)
  target_link_libraries(a6_grade PRIVATE a6_suite a6_report a6_rubric CLI11::CLI11 GTest::gtest)
  # The reference force models the probe of tasks 3 and 5 asks for (they stay in a6_grade).
  target_include_directories(a6_grade PRIVATE ${PROJECT_SOURCE_DIR}/tests/support)
  target_compile_definitions(a6_grade PRIVATE
    A6_DEFAULT_RUBRIC="${A6_DEFAULT_RUBRIC}" A6_FORCE_MODELS="${A6_FORCE_MODELS}")
  target_compile_options(a6_grade PRIVATE ${A6_WARNINGS})

  # The other helpers' parts, as they land.
  if(TARGET a6_intake)
    target_link_libraries(a6_grade PRIVATE a6_intake)
    target_compile_definitions(a6_grade PRIVATE A6_GRADE_HAVE_INTAKE)
  endif()
  if(TARGET a6_build)
    target_link_libraries(a6_grade PRIVATE a6_build)
    target_compile_definitions(a6_grade PRIVATE A6_GRADE_HAVE_BUILD)
  endif()
  if(TARGET a6_probe_client)
    target_link_libraries(a6_grade PRIVATE a6_probe_client)
    target_compile_definitions(a6_grade PRIVATE A6_GRADE_HAVE_PROBE)
  endif()
endif()

if(TARGET a6_grade AND TARGET a6_grader_kit)
  add_dependencies(a6_grade a6_grader_kit)  # grading builds against the kit
endif()

# The golden-image checks, once tests/golden offers them without student code (an OBJECT library
# a6_golden_checks with golden_checks.h: see grader/main.cpp).
if(TARGET a6_grade AND TARGET a6_golden_checks)
  target_link_libraries(a6_grade PRIVATE a6_golden_checks)
  target_compile_definitions(a6_grade PRIVATE A6_GRADE_HAVE_GOLDEN)
endif()
