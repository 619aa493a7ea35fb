# psb-particles-bench: the CH14 scene at 1k/10k/100k particles, ms per step for each integrator and
# how many particles end below the ground. A plain timing executable that prints the docs/ch14.md table.
add_executable(psb-particles-bench ${CMAKE_CURRENT_LIST_DIR}/particles_bench.cpp)
target_link_libraries(psb-particles-bench PRIVATE psb_scenes psb_physics psb_options)
