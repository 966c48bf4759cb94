# The reference physics (grader/reference/): physics.inc, every law the grader compares against,
# the reference steppers built on it and the cloth builder (a6_reference), which the hidden checks, the mistake
# library and the replays run. Read by the top-level CMakeLists.txt before tests/ and grader/ (the
# hidden checks need it in a build without the grader too). Graders' material: a student release
# has no such folder, so there the target does not exist (nor does any of its users).
if(EXISTS ${CMAKE_CURRENT_LIST_DIR}/steppers.cpp)
  add_library(a6_reference STATIC ${CMAKE_CURRENT_LIST_DIR}/steppers.cpp
                                 ${CMAKE_CURRENT_LIST_DIR}/cloth.cpp)
  target_include_directories(a6_reference PUBLIC ${CMAKE_CURRENT_LIST_DIR}/..)
  # Plain data and contact geometry only: no student code, no a6_framework.
  target_link_libraries(a6_reference PUBLIC a6_harness_api a6_core)
  target_compile_options(a6_reference PRIVATE ${A6_WARNINGS})
endif()
