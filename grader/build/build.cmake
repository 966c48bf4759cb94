# Build (build/): the seven task files to a linked probe, each file compiled alone in the sandbox
# (a6_build), and the kit the build links against (a6_grader_kit, described by
# BUILD/grader/kit.json). Takes a6_sandbox and the probe's link line (probe/probe.cmake).
#
# The kit folder, BUILD/grader/kit/, holds what a submission's compile reads besides the system
# headers, so that the sandbox can hide the rest of the repository and the build tree:
#   include/a6/*.h        the student API headers (and nothing else of the framework)
#   pch/a6_pch.h(.gch)    Eigen/Core and the standard headers the a6 headers use, precompiled
#                         with the kit's flags and force-included (-include): a compile takes a
#                         quarter of the time
#   starter/<task>.o      the starter's seven objects (a missing or broken task file falls back)
#   starter/<task>.syms   the symbols each defines, demangled (to tell which task a link error
#                         about an undefined symbol belongs to)
# The probe's main object and libraries stay where probe/probe.cmake builds them (its
# A6_PROBE_LINK_MAIN and A6_PROBE_LINK_LIBRARIES); kit.json names them and the build reveals them.

# Script mode: cmake -DNM=... -DOBJECT=... -DOUT=... -P build.cmake writes the symbols
# OBJECT defines, one per line.
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
target_compile_options(a6_build PRIVATE ${A6_WARNINGS})

# The student API headers, staged alone (the compiler gets -I to this folder only).
file(GLOB A6_KIT_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/framework/include/a6/*.h)
set(staged_headers "")
foreach(header IN LISTS A6_KIT_HEADERS)
  get_filename_component(name ${header} NAME)
  list(APPEND staged_headers ${A6_KIT_DIR}/include/a6/${name})
endforeach()
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

# The flags every task file is compiled with: those of the project's own build (C++17, -O2,
# no FMA contraction, NDEBUG as in the default RelWithDebInfo build), warnings on so that
# students see them, plain diagnostics, and only the staged headers plus Eigen's.
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

# The precompiled header: built with exactly the flags above (GCC uses it only then; otherwise
# it reads a6_pch.h itself, slower but the same).
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
# Both compiled through the build's compiler cache when it has one (cmake/A6FastBuild.cmake):
# the same bytes as the compiler's, which a second build or a copy of the checkout reuses.
add_custom_command(
  OUTPUT ${A6_KIT_PCH}.gch
  COMMAND ${CMAKE_CXX_COMPILER_LAUNCHER} ${CMAKE_CXX_COMPILER} ${A6_KIT_COMPILE_FLAGS}
          -x c++-header ${A6_KIT_PCH} -o ${A6_KIT_PCH}.gch
  DEPENDS ${A6_KIT_PCH} ${staged_headers}
  COMMENT "Precompiling the grader kit's header"
  VERBATIM)
list(APPEND kit_files ${A6_KIT_PCH}.gch)
list(APPEND A6_KIT_COMPILE_FLAGS -include ${A6_KIT_PCH})

# Known texts: the solution's files and their objects, beside the kit (never in it: the kit
# folder is in every compile's view, this one is hidden with the build tree), each compiled
# exactly as the grader compiles a submitted file (the kit's compiler and flags, the file's folder
# mapped away). A submitted file equal to one byte for byte is linked with its object instead of
# being compiled (Kit::knownObjects): the grader's own texts are all that gradings share.
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

# What the probe links besides the student's seven objects (probe/probe.cmake's link line).
set(A6_KIT_PROBE_MAIN ${A6_PROBE_LINK_MAIN})
set(A6_KIT_MODELS_MAIN ${A6_PROBE_LINK_MODELS_MAIN})
set(A6_KIT_LINK_INPUTS ${A6_PROBE_LINK_LIBRARIES})

# kit.json (see Kit in build.h).
# Items may be generator expressions that expand to lists ($<TARGET_OBJECTS:...>).
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
a6_json_array(json_main ${A6_KIT_PROBE_MAIN})
a6_json_array(json_models_main ${A6_KIT_MODELS_MAIN})
a6_json_array(json_link ${A6_KIT_LINK_INPUTS})
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
