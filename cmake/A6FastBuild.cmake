# Faster rebuilds, each used when the machine has it and never required (issue 12, "a one-second
# loop"; scripts/bench-student-loop.sh measures it):
#   - a fast linker, mold or else lld: relinking the tests after one edit takes a third of the
#     time GNU ld takes;
#   - ccache, with paths taken relative to the source folder, so that another copy of the same
#     files (the student release and the Gradescope package that the tests build, a second
#     checkout) reuses what this one compiled instead of compiling it again.
# Include it before any target is defined. Sets A6_LINKER and A6_CCACHE_PROGRAM ("" when unused).

option(A6_FAST_LINKER "Link with mold or lld when the compiler can" ON)
option(A6_CCACHE "Compile through ccache when it is installed and its cache is writable" ON)

include(CheckLinkerFlag)

set(A6_LINKER "")
if(A6_FAST_LINKER)
  foreach(linker mold lld)
    check_linker_flag(CXX "-fuse-ld=${linker}" A6_LINKER_${linker}_WORKS)
    if(A6_LINKER_${linker}_WORKS)
      add_link_options(-fuse-ld=${linker})
      set(A6_LINKER ${linker})
      break()
    endif()
  endforeach()
endif()

set(A6_CCACHE_PROGRAM "")
if(A6_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(A6_CCACHE_FOUND ccache)
  find_program(A6_ENV_PROGRAM env)
  if(A6_CCACHE_FOUND AND A6_ENV_PROGRAM)
    # A cache it cannot write would fail every compile: then it is left out.
    execute_process(COMMAND ${A6_CCACHE_FOUND} --get-config=cache_dir
                    OUTPUT_VARIABLE cache_dir OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
    set(probe "${cache_dir}")
    while(probe AND NOT EXISTS "${probe}")
      get_filename_component(probe "${probe}" DIRECTORY)
    endwhile()
    if(rc EQUAL 0 AND probe)
      execute_process(COMMAND test -w "${probe}" RESULT_VARIABLE writable)
      if(writable EQUAL 0)
        set(A6_CCACHE_PROGRAM ${A6_CCACHE_FOUND})
      endif()
    endif()
  endif()
  if(A6_CCACHE_PROGRAM)
    # base_dir: paths under the source folder are hashed relative to it; hash_dir off: the build
    # folder's name (in the debug info) does not split the cache; the sloppiness the precompiled
    # headers need (cmake/A6Student.cmake, grader/build/build.cmake), each hashed by the checksum
    # cmake/ccache-pch.sh writes beside it (pch_external_checksum) rather than read whole, 90 MB,
    # by every compile that uses it: 0.6 s of each cache hit. An entry keeps the way it was made,
    # so these entries have a namespace of their own.
    set(CMAKE_CXX_COMPILER_LAUNCHER
        sh ${CMAKE_CURRENT_LIST_DIR}/ccache-pch.sh ${A6_ENV_PROGRAM}
        CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_NOHASHDIR=true
        CCACHE_SLOPPINESS=pch_defines,time_macros CCACHE_PCH_EXTSUM=true
        CCACHE_NAMESPACE=a6-pch-sums ${A6_CCACHE_PROGRAM})
  endif()
endif()
if(NOT A6_LINKER)
  set(linker_said "the default")
else()
  set(linker_said "${A6_LINKER}")
endif()
if(NOT A6_CCACHE_PROGRAM)
  set(ccache_said "off")
else()
  set(ccache_said "${A6_CCACHE_PROGRAM}")
endif()
message(STATUS "a6: linker: ${linker_said}; compiler cache: ${ccache_said}")

# a6_line_tables_only(): in the calling folder, the default build (RelWithDebInfo) keeps line
# tables only (-g1) instead of full debug information: backtraces still name files and lines,
# and the grader's template-heavy files (JSON, GoogleTest) compile in about half the time
# (grader/harness/wire.cpp: 22 s with no debug information, 34 s with -g1, 52 s with -g).
macro(a6_line_tables_only)
  string(REGEX REPLACE "(^| )-g( |$)" "\\1-g1\\2" CMAKE_CXX_FLAGS_RELWITHDEBINFO
                       "${CMAKE_CXX_FLAGS_RELWITHDEBINFO}")
endmacro()

# a6_checking_code(): line tables, and -O1 in place of -O2, for the code that checks (the grader,
# the tests): it is most of what a student's first scripts/check.sh compiles, and compiles a
# quarter faster so (scripts/bench-first-hour.sh). Its numbers do not change: without fast-math
# and with -ffp-contract=off, every optimisation level computes the same IEEE results. The code
# that is checked (the student's files, the solution, the framework's physics) keeps -O2.
macro(a6_checking_code)
  a6_line_tables_only()
  string(REGEX REPLACE "(^| )-O2( |$)" "\\1-O1\\2" CMAKE_CXX_FLAGS_RELWITHDEBINFO
                       "${CMAKE_CXX_FLAGS_RELWITHDEBINFO}")
endmacro()

# a6_configured_path(<target> <name> <path>): the path (generator expressions allowed) as
# `a6::paths::<name>`, a `const char[]` defined in a file of its own that is generated for
# <target> (code declares `namespace a6::paths { extern const char <name>[]; }`). A path given
# as a -D definition would make the large file that reads it compile differently in every copy
# of the checkout (ccache hashes the definitions as they are); kept out of it, that file is
# compiled once for all copies (the student release, the Gradescope package, a second checkout).
function(a6_configured_path target name path)
  set(file ${CMAKE_CURRENT_BINARY_DIR}/a6_paths/${target}_${name}.cpp)
  file(GENERATE OUTPUT ${file} CONTENT
       "// Generated (cmake/A6FastBuild.cmake, a6_configured_path): a path of this build.
namespace a6::paths {
extern const char ${name}[];
const char ${name}[] = \"${path}\";
}  // namespace a6::paths
")
  target_sources(${target} PRIVATE ${file})
endfunction()

# a6_embedded_text(<target> <name> <file>): the text of <file> (a page's CSS or JavaScript, kept
# as a file of its own) as `a6::assets::<name>`, a `const char[]` that begins with a newline,
# defined in a file generated for <target> when CMake configures (an edit of <file> configures
# again). Code declares `namespace a6::assets { extern const char <name>[]; }`.
function(a6_embedded_text target name file)
  file(READ ${file} text)
  if(text MATCHES "\\)a6asset\"")
    message(FATAL_ERROR "${file} holds ')a6asset\"', which ends its embedding")
  endif()
  set(out ${CMAKE_CURRENT_BINARY_DIR}/a6_assets/${target}_${name}.cpp)
  file(RELATIVE_PATH source ${PROJECT_SOURCE_DIR} ${file})  # the same text in every checkout
  set(content "// Generated (cmake/A6FastBuild.cmake, a6_embedded_text) from ${source}.
namespace a6::assets {
extern const char ${name}[];
const char ${name}[] = R\"a6asset(
${text})a6asset\";
}  // namespace a6::assets
")
  set(old "")
  if(EXISTS ${out})
    file(READ ${out} old)
  endif()
  if(NOT old STREQUAL content)
    file(WRITE ${out} "${content}")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file})
  target_sources(${target} PRIVATE ${out})
endfunction()

# a6_bundled(<target> <count> <file>...): compiles the given .cpp files of <target> <count> to a
# translation unit (a bundle, generated in the build folder, that includes them), so that the
# headers they share (GoogleTest, Eigen, nlohmann-json: about 3 s of every file) are read once
# per bundle: most of what a student's first scripts/check.sh compiles is the suite and the
# grading, and that build takes about a fifth less time (scripts/bench-first-hour.sh). CMake's
# own UNITY_BUILD includes each file by its absolute path, so that no two copies of the checkout
# could share a bundle through ccache; these include them by a path relative to the bundle. A
# file's own names must not meet another's in its bundle (tests/format/bundles_test.sh says
# which, on the list of bundles this writes to a6_bundles.txt in the build folder).
function(a6_bundled target count)
  get_target_property(source_dir ${target} SOURCE_DIR)
  get_target_property(binary_dir ${target} BINARY_DIR)
  # Relative between real paths: a build folder reached through a link still finds the files
  # (the top build folder exists by now, the target's may not yet).
  file(RELATIVE_PATH below ${CMAKE_BINARY_DIR} ${binary_dir})
  file(REAL_PATH ${CMAKE_BINARY_DIR} top)
  set(dir ${top}/${below}/a6_bundles)
  get_property(k TARGET ${target} PROPERTY A6_BUNDLES_MADE)  # the bundles of earlier calls
  if(NOT k)
    set(k 0)
  endif()
  set(n 0)        # files in the bundle being written
  set(placed 0)   # files of this call seen so far
  set(content "")
  list(LENGTH ARGN all)
  foreach(file IN LISTS ARGN)
    file(REAL_PATH ${file} path BASE_DIRECTORY ${source_dir})
    set_source_files_properties(${file} TARGET_DIRECTORY ${target} PROPERTIES HEADER_FILE_ONLY ON)
    file(RELATIVE_PATH relative ${dir} ${path})
    string(APPEND content "#include \"${relative}\"\n")
    math(EXPR n "${n} + 1")
    math(EXPR placed "${placed} + 1")
    if(n EQUAL count OR placed EQUAL all)
      set(bundle ${dir}/${target}_${k}.cpp)
      file(GENERATE OUTPUT ${bundle} CONTENT
           "// Generated (cmake/A6FastBuild.cmake, a6_bundled): files of ${target}, compiled as one.\n${content}")
      target_sources(${target} PRIVATE ${bundle})
      set_property(GLOBAL APPEND PROPERTY A6_BUNDLES ${bundle})
      math(EXPR k "${k} + 1")
      set(n 0)
      set(content "")
    endif()
  endforeach()
  set_property(TARGET ${target} PROPERTY A6_BUNDLES_MADE ${k})
endfunction()
