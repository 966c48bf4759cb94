# Wrong versions and correct alternatives (tests/wrong/<name>/, tests/alternative/<name>/) are
# kept as the change they make to the solution: <file>.cpp.patch, a unified diff against
# solution/<file>.cpp (docs/instructor.md, "Wrong versions"). Configuring applies each, exactly
# (no fuzz), into BUILD/variants/<kind>/<name>/<file>.cpp beside a copy of the folder's other
# files (EXPECT, README.md). A change of the solution carries into every variant whose patch
# does not touch the lines around it; the configure names every patch that no longer applies,
# and stops. Editing a patch or the solution configures again.
find_program(A6_PATCH patch)

# a6_variant_dir(<out-var> <kind> <name>): the folder the variant is built from.
function(a6_variant_dir out kind name)
  if(NOT A6_PATCH)
    message(FATAL_ERROR "the 'patch' program is missing (scripts/install-deps.sh installs it): "
                        "the wrong versions and alternatives are patches of the solution")
  endif()
  set(src ${PROJECT_SOURCE_DIR}/tests/${kind}/${name})
  set(dest ${CMAKE_BINARY_DIR}/variants/${kind}/${name})
  file(GLOB files ${src}/*)
  foreach(file IN LISTS files)
    get_filename_component(fname ${file} NAME)
    set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file})
    if(fname MATCHES "\\.cpp$")
      message(FATAL_ERROR "tests/${kind}/${name}/${fname} is a whole file: keep it as its change "
              "to the solution (scripts/instructor.sh variant ${kind}/${name} FILE writes "
              "tests/${kind}/${name}/${fname}.patch; docs/instructor.md, \"Wrong versions\")")
    elseif(fname MATCHES "^(.+\\.cpp)\\.patch$")
      a6_apply_variant_patch(${file} ${CMAKE_MATCH_1} ${dest} "tests/${kind}/${name}/${fname}")
    else()
      configure_file(${file} ${dest}/${fname} COPYONLY)
    endif()
  endforeach()
  set(${out} ${dest} PARENT_SCOPE)
endfunction()

# a6_apply_variant_patch(<patch> <file.cpp> <dest> <shown-as>): dest/<file.cpp>, rewritten only
# when its text changes (so a reconfigure rebuilds nothing that did not change).
function(a6_apply_variant_patch patch target dest shown)
  set(base ${PROJECT_SOURCE_DIR}/solution/${target})
  set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${base})
  set(scratch ${CMAKE_BINARY_DIR}/variants/.patched)
  file(MAKE_DIRECTORY ${scratch})
  execute_process(
    COMMAND ${A6_PATCH} --silent --fuzz=0 --reject-file=- --no-backup-if-mismatch
            --output=${scratch}/${target} --input=${patch} ${base}
    RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT status EQUAL 0)
    # Every such patch is named before the configure stops.
    message(SEND_ERROR "${shown} no longer applies to solution/${target} (the solution changed "
            "where the variant changes it): write the variant again over the new solution and "
            "make its patch anew (docs/instructor.md, \"Wrong versions\").\n${log}")
    return()
  endif()
  configure_file(${scratch}/${target} ${dest}/${target} COPYONLY)
endfunction()
