# psb-micro-bench: Google Benchmark microbenchmarks of the hot functions (raycasts, line tests,
# manifolds, ApplyImpulse, integrator steps, spring force). Skipped with a message if benchmark is missing.
find_package(benchmark QUIET)
if(benchmark_FOUND)
  add_executable(psb-micro-bench ${CMAKE_CURRENT_LIST_DIR}/micro_bench.cpp)
  target_link_libraries(psb-micro-bench PRIVATE psb_scenes psb_physics psb_view psb_geometry psb_math psb_options
                                                 benchmark::benchmark)
else()
  message(STATUS "Google Benchmark not found: psb-micro-bench and psb-model-cost not built (scripts/install-deps.sh)")
endif()
