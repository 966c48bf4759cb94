# Mistakes (mistakes/): the student's answers to the public checks (checks/transcript.h) beside
# a library of known mistakes, each named with one sentence for the student (DESIGN.md). Gives
# a6_mistakes. The library (mistakes/library/: the tasks' reference answers and their known
# mistakes) is graders' material: a student release has none, and no_library.cpp names nothing.
set(a6_mistakes_dir ${CMAKE_CURRENT_SOURCE_DIR}/mistakes)
if(EXISTS ${a6_mistakes_dir}/library/library.cpp)
  set(a6_mistake_models)
  foreach(part library task1 task2 task3 task4 task5 task6 task7 parts measured/fit
               measured/spring measured/forces measured/stepping measured/cloth
               measured/particles measured/joints measured/diagnose)
    list(APPEND a6_mistake_models ${a6_mistakes_dir}/library/${part}.cpp)
  endforeach()
else()
  set(a6_mistake_models ${a6_mistakes_dir}/no_library.cpp)
endif()
add_library(a6_mistakes STATIC ${a6_mistakes_dir}/mistakes.cpp ${a6_mistake_models})
target_include_directories(a6_mistakes PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
# Plain data and contact geometry only: no student code, no a6_framework.
target_link_libraries(a6_mistakes PUBLIC a6_harness_api a6_core)
if(TARGET a6_reference)
  target_link_libraries(a6_mistakes PRIVATE a6_reference)  # the physics' forms, the steppers
endif()
target_compile_options(a6_mistakes PRIVATE ${A6_WARNINGS})
