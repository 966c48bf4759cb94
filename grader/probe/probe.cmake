# The probe (probe/): the wire format, the probe's main, what a submission's probe links against
# (a6_probe_kit, the link line A6_PROBE_LINK_*), and the client that talks to a sandboxed probe
# (a6_probe_client). Takes a6_sandbox (sandbox/sandbox.cmake).

# The harness's plain data (JSON documents sent as MessagePack) and the reference forces over a
# pipe: both ends.
add_library(a6_wire STATIC ${PROJECT_SOURCE_DIR}/framework/harness/wire.cpp
                           ${PROJECT_SOURCE_DIR}/framework/harness/force_channel.cpp)
target_link_libraries(a6_wire PUBLIC a6_harness_api nlohmann_json::nlohmann_json)

# The probe's main, built twice; neither holds a reference model. a6_probe_main serves every
# request; a6_probe_main_models is linked into a second probe that serves only the requests of
# tasks 3 and 5 that ask for the reference forces, which it asks the grader for, force by force,
# on two more pipes (framework/harness/force_channel.h; grader/DESIGN.md, "Two probes").
add_library(a6_probe_main OBJECT ${CMAKE_CURRENT_SOURCE_DIR}/probe/probe_main.cpp)
add_library(a6_probe_main_models OBJECT ${CMAKE_CURRENT_SOURCE_DIR}/probe/probe_main.cpp)
target_compile_definitions(a6_probe_main_models PRIVATE A6_REMOTE_FORCES)
target_link_libraries(a6_probe_main PRIVATE a6_harness_api nlohmann_json::nlohmann_json)
target_link_libraries(a6_probe_main_models PRIVATE a6_harness_api nlohmann_json::nlohmann_json)

# The kit: everything a probe links besides its main and the seven student objects.
add_library(a6_probe_kit STATIC $<TARGET_OBJECTS:a6_framework> $<TARGET_OBJECTS:a6_core>
                                $<TARGET_OBJECTS:a6_wire>)
set_target_properties(a6_probe_kit PROPERTIES LINKER_LANGUAGE CXX)
target_link_libraries(a6_probe_kit INTERFACE a6_harness_api box2d::box2d)

# How a submission's probe is linked (what grader/build/build.cpp runs, in the sandbox):
#   <compiler> -o <probe> <A6_PROBE_LINK_MAIN> <the seven task objects> <A6_PROBE_LINK_LIBRARIES>
# For build/build.cmake (read after this file) and for the tests' hostile probes.
set(A6_PROBE_LINK_COMPILER ${CMAKE_CXX_COMPILER})
set(A6_PROBE_LINK_MAIN "$<TARGET_OBJECTS:a6_probe_main>")
set(A6_PROBE_LINK_MODELS_MAIN "$<TARGET_OBJECTS:a6_probe_main_models>")
set(A6_PROBE_LINK_LIBRARIES
    "$<TARGET_FILE:a6_probe_kit>" "$<TARGET_LINKER_FILE:box2d::box2d>")
set(A6_PROBE_LINK_TARGETS a6_probe_main a6_probe_main_models a6_probe_kit)  # build these before linking a probe
set(A6_PROBE_EXTRA_LINK "")  # what kit.json adds after box2d: nothing (no libseccomp)
list(JOIN A6_PROBE_LINK_LIBRARIES " " _a6_probe_libs)
file(GENERATE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/probe_link.txt CONTENT
"# How a submission's probe is linked (grader/cmake/probe.cmake): the compiler, then -o and the
# probe's path, then the probe main object, then the seven task objects in task order (spring,
# forces, time_stepping, cloth, particle_system, joints, implicit), then the libraries, in this
# order.
compiler=${CMAKE_CXX_COMPILER}
main=${A6_PROBE_LINK_MAIN}
libraries=${_a6_probe_libs}
line=${CMAKE_CXX_COMPILER} -o PROBE ${A6_PROBE_LINK_MAIN} SPRING.o FORCES.o TIME_STEPPING.o CLOTH.o PARTICLE_SYSTEM.o JOINTS.o IMPLICIT.o ${_a6_probe_libs}
")
unset(_a6_probe_libs)

# Probes of the solution and of the starter, for the tests: the second probe's main, so that one
# probe answers every request of the suite (the test gives it the reference forces to ask for).
set(probe_sets starter)
if(A6_HAVE_SOLUTION)
  list(APPEND probe_sets solution)
endif()
foreach(set IN LISTS probe_sets)
  add_executable(a6_probe_${set})
  target_link_libraries(a6_probe_${set} PRIVATE a6_probe_main_models ${A6_${set}_OBJECTS}
                                                a6_probe_kit)
endforeach()


# The StudentCode that talks to a sandboxed probe.
add_library(a6_probe_client STATIC ${CMAKE_CURRENT_SOURCE_DIR}/probe/probe_client.cpp
                                   ${CMAKE_CURRENT_SOURCE_DIR}/probe/probe_pair.cpp)
target_link_libraries(a6_probe_client PUBLIC a6_sandbox a6_wire a6_harness_api)
