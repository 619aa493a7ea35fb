# psb-rigid-bench: boxpile N, pyramid B, tower H and bounce e with the book's solver settings; ms per
# step and quality figures. A plain timing executable that prints the docs/ch15.md tables.
add_executable(psb-rigid-bench ${CMAKE_CURRENT_LIST_DIR}/rigid_bench.cpp)
target_link_libraries(psb-rigid-bench PRIVATE psb_scenes psb_physics psb_options)
