# Scoring (scoring/): the points the rubric gives for the checks' outcomes (score.cpp). Gives
# a6_score.
add_library(a6_score STATIC ${CMAKE_CURRENT_SOURCE_DIR}/scoring/score.cpp)
target_include_directories(a6_score PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(a6_score PUBLIC a6_rubric)
