# The layer under every stage (sandbox/): processes (process.h) and the sandbox that runs the
# compiler, the linker and the probe (sandbox.h, plan.h). Gives a6_process and a6_sandbox.
find_package(PkgConfig REQUIRED)
pkg_check_modules(SECCOMP REQUIRED IMPORTED_TARGET GLOBAL libseccomp)
find_package(Threads REQUIRED)

add_library(a6_process STATIC ${CMAKE_CURRENT_SOURCE_DIR}/sandbox/process.cpp)
target_include_directories(a6_process PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})

add_library(a6_sandbox STATIC ${CMAKE_CURRENT_SOURCE_DIR}/sandbox/sandbox.cpp
                              ${CMAKE_CURRENT_SOURCE_DIR}/sandbox/output.cpp
                              ${CMAKE_CURRENT_SOURCE_DIR}/sandbox/plan.cpp
                              ${CMAKE_CURRENT_SOURCE_DIR}/sandbox/child.cpp
                              ${CMAKE_CURRENT_SOURCE_DIR}/sandbox/filter.cpp)
target_include_directories(a6_sandbox PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(a6_sandbox PUBLIC a6_process PkgConfig::SECCOMP Threads::Threads)

# The init of each sandboxed command's pid namespace (keeper_main.cpp).
add_executable(a6_keeper ${CMAKE_CURRENT_SOURCE_DIR}/sandbox/keeper_main.cpp)
add_dependencies(a6_sandbox a6_keeper)
a6_configured_path(a6_sandbox keeper "$<TARGET_FILE:a6_keeper>")
