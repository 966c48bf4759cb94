# Student file sets: the seven task files, each compiled as its own object library so that a set
# can mix files (a submission with one file missing falls back to the starter's; a wrong
# version replaces one file of the solution) without recompiling the others.

# The task files, in task order, as the one table of the tasks lists them
# (framework/harness/tasks.h, courseTasks(): its quoted "<name>.cpp" strings), without ".cpp";
# A6_TASK_NUMBERS counts them (1 2 ... N).
file(READ ${PROJECT_SOURCE_DIR}/framework/harness/tasks.h a6_tasks_h)
string(REGEX MATCHALL "\"[a-z_]+\\.cpp\"" A6_TASK_FILES "${a6_tasks_h}")
list(TRANSFORM A6_TASK_FILES REPLACE "^\"([a-z_]+)\\.cpp\"$" "\\1")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${PROJECT_SOURCE_DIR}/framework/harness/tasks.h)
list(LENGTH A6_TASK_FILES a6_task_count)
if(a6_task_count EQUAL 0)
  message(FATAL_ERROR "framework/harness/tasks.h lists no task file")
endif()
set(A6_TASK_NUMBERS)
foreach(task RANGE 1 ${a6_task_count})
  list(APPEND A6_TASK_NUMBERS ${task})
endforeach()
set(A6_WARNINGS -Wall -Wextra)

# a6_student_set(<name> <dir> [STARTER] [FALLBACK <set>])
#   Defines the object libraries a6_<name>_<file> for every task file found in <dir>; a file
#   missing from <dir> is taken from the set FALLBACK (which must exist). Sets
#   A6_<name>_OBJECTS (in the caller's scope) to the seven object libraries of the set.
#   STARTER: the stubs leave parameters unused on purpose; do not warn about that.
# The headers every task file may use without naming them, precompiled once for all the sets:
# the same list as the grader kit's (grader/build/build.cmake), so that a file builds here
# exactly when it builds in the grader. A task file then compiles in about 0.4 s instead of 1.1 s.
set(A6_STUDENT_PCH_HEADERS <Eigen/Core> <algorithm> <cmath> <cstdint> <deque> <functional>
                           <limits> <vector>)

function(a6_student_pch)
  if(TARGET a6_student_pch)
    return()
  endif()
  set(source ${CMAKE_BINARY_DIR}/a6_student_pch.cpp)
  file(GENERATE OUTPUT ${source} CONTENT "// Holds the student files' precompiled header.\n")
  add_library(a6_student_pch OBJECT ${source})
  target_link_libraries(a6_student_pch PUBLIC a6_api)
  target_compile_options(a6_student_pch PRIVATE ${A6_WARNINGS})
  target_precompile_headers(a6_student_pch PRIVATE ${A6_STUDENT_PCH_HEADERS})
endfunction()

function(a6_student_set name dir)
  cmake_parse_arguments(ARG "STARTER" "FALLBACK" "" ${ARGN})
  a6_student_pch()
  set(objects "")
  foreach(file IN LISTS A6_TASK_FILES)
    if(EXISTS "${dir}/${file}.cpp")
      set(target a6_${name}_${file})
      add_library(${target} OBJECT "${dir}/${file}.cpp")
      target_link_libraries(${target} PUBLIC a6_api)
      target_compile_options(${target} PRIVATE ${A6_WARNINGS})
      target_precompile_headers(${target} REUSE_FROM a6_student_pch)
      # The checked code at -O2 wherever its set is defined (tests/ builds its own code at -O1).
      target_compile_options(${target} PRIVATE $<$<CONFIG:RelWithDebInfo>:-O2>)
      if(ARG_STARTER)
        target_compile_options(${target} PRIVATE -Wno-unused-parameter)
      endif()
      list(APPEND objects ${target})
    elseif(ARG_FALLBACK)
      list(APPEND objects a6_${ARG_FALLBACK}_${file})
    else()
      message(FATAL_ERROR "student set '${name}': ${dir}/${file}.cpp is missing")
    endif()
  endforeach()
  set(A6_${name}_OBJECTS ${objects} PARENT_SCOPE)
endfunction()
