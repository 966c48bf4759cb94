# The rubric (TOML) and the reports (results.json, HTML, terminal): helper "rubric_report".
#
# toml++ (tomlplusplus::tomlplusplus) comes from cmake/A6Toml.cmake, at the top level.
add_library(a6_rubric STATIC ${CMAKE_CURRENT_SOURCE_DIR}/rubric.cpp)
target_include_directories(a6_rubric PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(a6_rubric PRIVATE tomlplusplus::tomlplusplus)
target_compile_options(a6_rubric PRIVATE ${A6_WARNINGS})

# report.h includes intake.h and build.h (their plain structs only), which include sandbox.h.
add_library(a6_report STATIC ${CMAKE_CURRENT_SOURCE_DIR}/report.cpp)
target_include_directories(a6_report PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(a6_report PUBLIC a6_rubric PRIVATE nlohmann_json::nlohmann_json)
target_compile_options(a6_report PRIVATE ${A6_WARNINGS})

# The default rubric, beside the grader in the build tree (the packaging step copies it too).
set(A6_DEFAULT_RUBRIC ${CMAKE_CURRENT_SOURCE_DIR}/rubric.toml)
