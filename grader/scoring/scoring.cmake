# Scoring (scoring/): the rubric (TOML, read with toml++: cmake/A6Toml.cmake) and the points it
# gives (score.cpp). Gives a6_rubric.
add_library(a6_rubric STATIC ${CMAKE_CURRENT_SOURCE_DIR}/scoring/rubric.cpp
                            ${CMAKE_CURRENT_SOURCE_DIR}/scoring/score.cpp)
target_include_directories(a6_rubric PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(a6_rubric PRIVATE tomlplusplus::tomlplusplus)
target_compile_options(a6_rubric PRIVATE ${A6_WARNINGS})
