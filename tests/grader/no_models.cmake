cmake_policy(SET CMP0054 NEW)
# Asserts that neither probe main (PLAIN, which serves every request, and MODELS, which serves the
# requests of tasks 3 and 5 that ask for the reference forces) holds a reference force model, and
# that the grader (GRADER), which answers the force requests, does: the check can fail. Run by
# ctest (grader_probe_main_holds_no_model).
foreach(which PLAIN MODELS GRADER)
  execute_process(COMMAND ${NM} -C ${${which}} OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "nm ${${which}} failed (${status})")
  endif()
  string(REGEX MATCHALL "reference(Spring|External)Force" found "${symbols}")
  if(NOT which STREQUAL "GRADER" AND found)
    message(FATAL_ERROR "the probe main ${${which}} holds the reference models: ${found}")
  elseif(which STREQUAL "GRADER" AND NOT found)
    message(FATAL_ERROR "no reference model found in ${GRADER}: is this check still looking?")
  endif()
endforeach()
message(STATUS "neither probe main holds a reference model; the grader does")
