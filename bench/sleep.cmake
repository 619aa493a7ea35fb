# psb-sleep-bench: a settled boxpile's ms per step asleep against the same state awake (docs/sleep.md).
add_executable(psb-sleep-bench ${CMAKE_CURRENT_LIST_DIR}/sleep_bench.cpp)
target_link_libraries(psb-sleep-bench PRIVATE psb_scenes psb_physics psb_options)
