# The class's picture (insights/): insights.html, written by a6_batch after each batch and by
# a6_insights for a Gradescope export; similarity with sim_c++, found at run time.
add_library(a6_insights_core STATIC ${CMAKE_CURRENT_SOURCE_DIR}/insights/insights.cpp
                                    ${CMAKE_CURRENT_SOURCE_DIR}/insights/page.cpp
                                    ${CMAKE_CURRENT_SOURCE_DIR}/insights/similarity.cpp)
target_include_directories(a6_insights_core PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
# The page's style and its sortable tables, kept as files (insights/assets/).
a6_embedded_text(a6_insights_core insights_css
                 ${CMAKE_CURRENT_SOURCE_DIR}/insights/assets/insights.css)
a6_embedded_text(a6_insights_core sort_tables_js
                 ${CMAKE_CURRENT_SOURCE_DIR}/insights/assets/sort_tables.js)
target_link_libraries(a6_insights_core PUBLIC a6_batch_core a6_process a6_intake
                      PRIVATE nlohmann_json::nlohmann_json)

add_executable(a6_insights ${CMAKE_CURRENT_SOURCE_DIR}/insights/insights_main.cpp)
target_link_libraries(a6_insights PRIVATE a6_insights_core CLI11::CLI11)
# The starter files, which the similarity discounts.
a6_configured_path(a6_insights starter "${PROJECT_SOURCE_DIR}/starter")
