# psb-model-cost: each demo scene's step as built and with an unused subsystem present.
find_package(benchmark QUIET)
if(benchmark_FOUND)
  add_executable(psb-model-cost ${CMAKE_CURRENT_LIST_DIR}/model_cost_bench.cpp)
  target_link_libraries(psb-model-cost PRIVATE psb_scenes psb_physics psb_options benchmark::benchmark)
  get_filename_component(PSB_MODEL_COST_REPO ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
  target_compile_definitions(psb-model-cost PRIVATE PSB_SOURCE_DIR="${PSB_MODEL_COST_REPO}")
endif()
