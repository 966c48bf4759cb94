# The rubric (rubric/): the TOML file read and checked (toml++: cmake/A6Toml.cmake), before any
# stage: the checks are matched with it at intake, their time limits come from it, the scoring
# stage gives its points. Gives a6_rubric.
add_library(a6_rubric STATIC ${CMAKE_CURRENT_SOURCE_DIR}/rubric/rubric.cpp)
target_include_directories(a6_rubric PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(a6_rubric PRIVATE tomlplusplus::tomlplusplus)
