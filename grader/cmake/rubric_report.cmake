# The rubric (TOML) and the reports (results.json, HTML, terminal): helper "rubric_report".
#
# toml++ 3 reads the rubric: the platform's package (libtomlplusplus-dev: Debian 12 and 13,
# Ubuntu 24.04), or, where there is none (Ubuntu 22.04, Gradescope's default image), the
# header-only copy in vendor/tomlplusplus/ that scripts/gradescope-package.sh puts into the
# autograder zip, taken from the packaging machine's package with its licence. The checkout never
# holds that copy.
find_package(tomlplusplus 3 QUIET)
if(NOT tomlplusplus_FOUND)
  find_path(A6_TOMLPLUSPLUS_INCLUDE toml++/toml.h
            PATHS ${PROJECT_SOURCE_DIR}/vendor/tomlplusplus/include NO_DEFAULT_PATH)
  if(NOT A6_TOMLPLUSPLUS_INCLUDE)
    message(FATAL_ERROR
      "toml++ 3 (the grader's rubric) is missing: install libtomlplusplus-dev "
      "(scripts/install-deps.sh; Debian 12 and 13, Ubuntu 24.04). Ubuntu 22.04 has no package: "
      "the Gradescope zip brings its own copy (vendor/tomlplusplus/).")
  endif()
  message(STATUS "toml++: the header-only copy in ${A6_TOMLPLUSPLUS_INCLUDE}")
  add_library(tomlplusplus::tomlplusplus INTERFACE IMPORTED)
  target_include_directories(tomlplusplus::tomlplusplus INTERFACE ${A6_TOMLPLUSPLUS_INCLUDE})
  target_compile_definitions(tomlplusplus::tomlplusplus INTERFACE TOML_HEADER_ONLY=1)
endif()

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
