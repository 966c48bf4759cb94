# toml++ 3, which reads the grader's rubric: takes nothing, gives A6_HAVE_TOML and, when true, the
# target tomlplusplus::tomlplusplus.
#
# Where from: the platform's package (libtomlplusplus-dev: Debian 12 and 13, Ubuntu 24.04), or,
# where there is none (Ubuntu 22.04, Gradescope's default image), the header-only copy in
# vendor/tomlplusplus/ that scripts/gradescope-package.sh puts into the autograder zip, taken from
# the packaging machine's package with its licence. A checkout or a student release never holds
# that copy: on Ubuntu 22.04 they build without the grader (the tests and the viewer still build;
# scripts/check.sh says what is missing).
find_package(tomlplusplus 3 QUIET)
if(tomlplusplus_FOUND)
  set(A6_HAVE_TOML ON)
  return()
endif()
find_path(A6_TOMLPLUSPLUS_INCLUDE toml++/toml.h
          PATHS ${PROJECT_SOURCE_DIR}/vendor/tomlplusplus/include NO_DEFAULT_PATH)
if(NOT A6_TOMLPLUSPLUS_INCLUDE)
  set(A6_HAVE_TOML OFF)
  return()
endif()
message(STATUS "toml++: the header-only copy in ${A6_TOMLPLUSPLUS_INCLUDE}")
add_library(tomlplusplus::tomlplusplus INTERFACE IMPORTED)
target_include_directories(tomlplusplus::tomlplusplus INTERFACE ${A6_TOMLPLUSPLUS_INCLUDE})
target_compile_definitions(tomlplusplus::tomlplusplus INTERFACE TOML_HEADER_ONLY=1)
set(A6_HAVE_TOML ON)
