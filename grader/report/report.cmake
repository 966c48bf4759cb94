# Report (report/): results.json (Gradescope's format), report.html and the terminal summary.
# Gives a6_report.
# report.h includes intake.h and build.h (their plain structs only), which include sandbox.h.
add_library(a6_report STATIC ${CMAKE_CURRENT_SOURCE_DIR}/report/report.cpp
                             ${CMAKE_CURRENT_SOURCE_DIR}/report/replay_html.cpp)
target_include_directories(a6_report PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
# The page's style and the replays' player, kept as files (report/assets/).
a6_embedded_text(a6_report report_css ${CMAKE_CURRENT_SOURCE_DIR}/report/assets/report.css)
a6_embedded_text(a6_report replay_player_js
                 ${CMAKE_CURRENT_SOURCE_DIR}/report/assets/replay_player.js)
target_link_libraries(a6_report PUBLIC a6_score PRIVATE a6_replay nlohmann_json::nlohmann_json)

# The default rubric, beside the grader in the build tree (the packaging step copies it too).
set(A6_DEFAULT_RUBRIC ${CMAKE_CURRENT_SOURCE_DIR}/rubric.toml)
