# psb-cloth-bench: the CH16 cloth at N = 15, 30, 60, 120 with the book's k: ms per step for each
# integrator, and the largest stable step per integrator (bisection over dt). Prints the docs/ch16.md tables.
add_executable(psb-cloth-bench ${CMAKE_CURRENT_LIST_DIR}/cloth_bench.cpp)
target_link_libraries(psb-cloth-bench PRIVATE psb_scenes psb_physics psb_options)
