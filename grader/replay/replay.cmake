# Replays (replay/): the student's runs of the imaged scenes beside the reference runs
# (tests/golden/replays/), and task 3's failed simulations beside the reference stepper (the
# mistakes library's), measured for the report. Gives a6_replay_view.
add_library(a6_replay_view STATIC ${CMAKE_CURRENT_SOURCE_DIR}/replay/replays.cpp)
target_include_directories(a6_replay_view PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(a6_replay_view PUBLIC a6_harness_api a6_replay a6_mistakes)
target_compile_options(a6_replay_view PRIVATE ${A6_WARNINGS})
