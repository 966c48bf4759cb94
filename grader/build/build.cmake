# Build (build/): the task files to a linked probe, each compiled alone in the sandbox
# (a6_build), and the kit it links against (a6_grader_kit, described by BUILD/grader/kit.json).
#
# The kit folder, BUILD/grader/kit/, holds all a compile reads besides the system headers, so
# that the sandbox can hide the rest of the repository and the build tree:
#   include/a6/*.h        the student API headers only
#   pch/a6_pch.h(.gch)    Eigen/Core and standard headers, precompiled and force-included (a
#                         compile takes a quarter of the time)
#   starter/<task>.o      the starter's objects (a missing or broken task file falls back)
#   starter/<task>.syms   the symbols each defines (whose task an undefined symbol is)
# The probe's main and libraries stay where probe/probe.cmake builds them; kit.json names them.

# Script mode (-DNM= -DOBJECT= -DOUT= -P build.cmake): the symbols OBJECT defines, one a line.
if(CMAKE_SCRIPT_MODE_FILE)
  execute_process(COMMAND ${NM} -C -g --defined-only -j ${OBJECT}
                  OUTPUT_FILE ${OUT} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${NM} failed on ${OBJECT}")
  endif()
  return()
endif()

set(A6_KIT_DIR ${CMAKE_CURRENT_BINARY_DIR}/kit)
set(A6_KIT_JSON ${CMAKE_CURRENT_BINARY_DIR}/kit.json)

add_library(a6_build STATIC ${CMAKE_CURRENT_SOURCE_DIR}/build/build.cpp
                            ${CMAKE_CURRENT_SOURCE_DIR}/build/kit.cpp)
target_include_directories(a6_build PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(a6_build PUBLIC a6_sandbox PRIVATE nlohmann_json::nlohmann_json)
a6_configured_path(a6_build kit_json "${A6_KIT_JSON}")

# The student API headers, staged alone (the compiler gets -I to this folder only).
file(GLOB A6_KIT_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/framework/include/a6/*.h)
set(staged_headers ${A6_KIT_HEADERS})
list(TRANSFORM staged_headers REPLACE "^.*/" "${A6_KIT_DIR}/include/a6/")
add_custom_command(
  OUTPUT ${staged_headers}
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${A6_KIT_DIR}/include
  COMMAND ${CMAKE_COMMAND} -E make_directory ${A6_KIT_DIR}/include/a6
  COMMAND ${CMAKE_COMMAND} -E copy ${A6_KIT_HEADERS} ${A6_KIT_DIR}/include/a6/
  DEPENDS ${A6_KIT_HEADERS}
  COMMENT "Staging the a6/ headers for the grader's kit"
  VERBATIM)

# The starter's objects and the symbols they define.
set(kit_files ${staged_headers})
foreach(file IN LISTS A6_TASK_FILES)
  set(object ${A6_KIT_DIR}/starter/${file}.o)
  add_custom_command(
    OUTPUT ${object} ${A6_KIT_DIR}/starter/${file}.syms
    COMMAND ${CMAKE_COMMAND} -E make_directory ${A6_KIT_DIR}/starter
    COMMAND ${CMAKE_COMMAND} -E copy $<TARGET_OBJECTS:a6_starter_${file}> ${object}
    COMMAND ${CMAKE_COMMAND} -DNM=${CMAKE_NM} -DOBJECT=${object}
            -DOUT=${A6_KIT_DIR}/starter/${file}.syms -P ${CMAKE_CURRENT_LIST_FILE}
    DEPENDS a6_starter_${file} $<TARGET_OBJECTS:a6_starter_${file}> ${CMAKE_CURRENT_LIST_FILE}
    COMMENT "Copying the starter's ${file}.o into the grader's kit"
    VERBATIM)
  list(APPEND kit_files ${object} ${A6_KIT_DIR}/starter/${file}.syms)
endforeach()

# The project's own flags (as the default RelWithDebInfo build), warnings for the students, plain
# diagnostics, and only the staged headers plus Eigen's and Box2D's.
set(A6_KIT_COMPILE_FLAGS -std=c++17 -O2 -DNDEBUG -ffp-contract=off ${A6_WARNINGS}
    -fdiagnostics-color=never -fmax-errors=20 -pipe -I${A6_KIT_DIR}/include)
foreach(dep Eigen3::Eigen box2d::box2d)
  get_target_property(dirs ${dep} INTERFACE_INCLUDE_DIRECTORIES)
  foreach(dir IN LISTS dirs)
    # /usr/include is searched anyway; -isystem on it would break libstdc++'s #include_next.
    if(dir AND NOT dir STREQUAL "/usr/include" AND NOT dir STREQUAL "/usr/local/include")
      list(APPEND A6_KIT_COMPILE_FLAGS -isystem ${dir})
    endif()
  endforeach()
endforeach()
list(REMOVE_DUPLICATES A6_KIT_COMPILE_FLAGS)

# The precompiled header, with exactly the flags above (else GCC reads a6_pch.h, slower).
set(A6_KIT_PCH ${A6_KIT_DIR}/pch/a6_pch.h)
file(GENERATE OUTPUT ${A6_KIT_PCH} CONTENT
"// Force-included into every task file the grader compiles (-include), precompiled beside it.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <vector>
")
# Through the build's compiler cache when it has one (cmake/A6FastBuild.cmake).
add_custom_command(
  OUTPUT ${A6_KIT_PCH}.gch
  COMMAND ${CMAKE_CXX_COMPILER_LAUNCHER} ${CMAKE_CXX_COMPILER} ${A6_KIT_COMPILE_FLAGS}
          -x c++-header ${A6_KIT_PCH} -o ${A6_KIT_PCH}.gch
  DEPENDS ${A6_KIT_PCH} ${staged_headers}
  COMMENT "Precompiling the grader kit's header"
  VERBATIM)
list(APPEND kit_files ${A6_KIT_PCH}.gch)
list(APPEND A6_KIT_COMPILE_FLAGS -include ${A6_KIT_PCH})

# Known texts: the solution's files and objects, compiled as the grader compiles a submitted
# file (its folder mapped away, so the objects are the same bytes), beside the kit, never in it:
# the kit folder is in every compile's view, this one is hidden with the build tree. A submitted
# file equal to one gets its object (Kit::knownObjects): the grader's own texts are all that
# gradings share.
set(A6_KNOWN_DIR "")
if(A6_HAVE_SOLUTION)
  set(A6_KNOWN_DIR ${CMAKE_CURRENT_BINARY_DIR}/known)
  foreach(file IN LISTS A6_TASK_FILES)
    set(source ${PROJECT_SOURCE_DIR}/solution/${file}.cpp)
    add_custom_command(
      OUTPUT ${A6_KNOWN_DIR}/${file}.o ${A6_KNOWN_DIR}/${file}.cpp
      COMMAND ${CMAKE_COMMAND} -E make_directory ${A6_KNOWN_DIR}
      COMMAND ${CMAKE_CXX_COMPILER_LAUNCHER} ${CMAKE_CXX_COMPILER} ${A6_KIT_COMPILE_FLAGS}
              -ffile-prefix-map=${PROJECT_SOURCE_DIR}/solution/= -c ${source}
              -o ${A6_KNOWN_DIR}/${file}.o
      COMMAND ${CMAKE_COMMAND} -E copy ${source} ${A6_KNOWN_DIR}/${file}.cpp
      DEPENDS ${source} ${A6_KIT_PCH}.gch ${staged_headers}
      COMMENT "Compiling the solution's ${file}.cpp as the grader would, for its known objects"
      VERBATIM)
    list(APPEND kit_files ${A6_KNOWN_DIR}/${file}.o ${A6_KNOWN_DIR}/${file}.cpp)
  endforeach()
endif()

# kit.json (see Kit in build.h). Items may be generator expressions that expand to lists.
function(a6_json_array out)
  set(items "")
  foreach(item IN LISTS ARGN)
    string(REPLACE "\\" "\\\\" item "${item}")
    string(REPLACE "\"" "\\\"" item "${item}")
    if(item MATCHES "^\\$<")
      list(APPEND items "\"$<JOIN:${item},\"$<COMMA> \">\"")
    else()
      list(APPEND items "\"${item}\"")
    endif()
  endforeach()
  list(JOIN items ", " joined)
  set(${out} "[${joined}]" PARENT_SCOPE)
endfunction()
a6_json_array(json_flags ${A6_KIT_COMPILE_FLAGS})
a6_json_array(json_main ${A6_PROBE_LINK_MAIN})
a6_json_array(json_models_main ${A6_PROBE_LINK_MODELS_MAIN})
a6_json_array(json_link ${A6_PROBE_LINK_LIBRARIES})
a6_json_array(json_secrets ${PROJECT_SOURCE_DIR} ${CMAKE_BINARY_DIR})
file(GENERATE OUTPUT ${A6_KIT_JSON} CONTENT "{
  \"compiler\": \"${CMAKE_CXX_COMPILER}\",
  \"compileFlags\": ${json_flags},
  \"probeMain\": ${json_main},
  \"modelsMain\": ${json_models_main},
  \"linkInputs\": ${json_link},
  \"starterObjects\": \"${A6_KIT_DIR}/starter\",
  \"knownObjects\": \"${A6_KNOWN_DIR}\",
  \"dir\": \"${A6_KIT_DIR}\",
  \"secrets\": ${json_secrets}
}
")

add_custom_target(a6_grader_kit ALL DEPENDS ${kit_files})
add_dependencies(a6_grader_kit ${A6_PROBE_LINK_TARGETS})
