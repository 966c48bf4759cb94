# Intake (intake/): a submission (a folder, an archive, one file) to the task files it holds.
# Gives a6_intake.
find_package(LibArchive 3 REQUIRED)

add_library(a6_intake STATIC ${CMAKE_CURRENT_SOURCE_DIR}/intake/intake.cpp
                             ${CMAKE_CURRENT_SOURCE_DIR}/intake/entries.cpp)
target_include_directories(a6_intake PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(a6_intake PRIVATE LibArchive::LibArchive)
