# Asserts that the probe's main that serves every request (PLAIN) holds no reference force model,
# and that the one for the requests of tasks 3 and 5 (MODELS) does: the check can fail. Run by
# ctest (grader_probe_main_holds_no_model).
foreach(which PLAIN MODELS)
  execute_process(COMMAND ${NM} -C ${${which}} OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "nm ${${which}} failed (${status})")
  endif()
  string(REGEX MATCHALL "reference(Spring|External)Force" found "${symbols}")
  if(which STREQUAL "PLAIN" AND found)
    message(FATAL_ERROR "the plain probe main ${PLAIN} holds the reference models: ${found}")
  elseif(which STREQUAL "MODELS" AND NOT found)
    message(FATAL_ERROR "no reference model found in ${MODELS}: is this check still looking?")
  endif()
endforeach()
message(STATUS "the plain probe main holds no reference model")
