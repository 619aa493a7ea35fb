# psb-sweep: reference problems x settings -> CSV (docs/sweep.md). Links the GL-free layers only.
add_executable(psb-sweep ${CMAKE_CURRENT_LIST_DIR}/sweep/SweepMain.cpp ${CMAKE_CURRENT_LIST_DIR}/sweep/Sweep.cpp
                         ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsParticle.cpp
                         ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsRigid.cpp
                         ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsCloth.cpp)
target_link_libraries(psb-sweep PRIVATE psb_scenes psb_physics psb_files psb_options)

# CI runs the small grid and checks what its numbers must show (tests/bench/sweep_quick_test.sh).
if(PSB_BUILD_TESTS)
  add_test(NAME sweep.quick COMMAND sh ${PROJECT_SOURCE_DIR}/tests/bench/sweep_quick_test.sh
                                    $<TARGET_FILE:psb-sweep> ${CMAKE_CURRENT_BINARY_DIR}/sweep-quick)
  set_tests_properties(sweep.quick PROPERTIES LABELS bench TIMEOUT 600)
  # The CSV is written whole or not at all: a write failure (file-size limit) is exit 3, no file, no temporary.
  add_test(NAME sweep.output COMMAND sh ${PROJECT_SOURCE_DIR}/tests/app/sweep_output_test.sh $<TARGET_FILE:psb-sweep>
                                     ${CMAKE_CURRENT_BINARY_DIR}/sweep-output)
  set_tests_properties(sweep.output PROPERTIES LABELS bench TIMEOUT 120)
endif()

# CI runs the shards through GNU parallel and the Slurm script, and checks the merges against one unsharded run
# (tests/bench/sweep_parallel_test.sh; skipped, exit 77, without GNU parallel).
if(PSB_BUILD_TESTS)
  add_test(NAME sweep.parallel COMMAND sh ${PROJECT_SOURCE_DIR}/tests/bench/sweep_parallel_test.sh ${PROJECT_SOURCE_DIR}
                                       $<TARGET_FILE:psb-sweep> ${CMAKE_CURRENT_BINARY_DIR}/sweep-parallel)
  set_tests_properties(sweep.parallel PROPERTIES LABELS bench TIMEOUT 600 SKIP_RETURN_CODE 77)
endif()

# The committed results are today's: a fixed sample of docs/sweep/results.csv re-run (sweep_reproduce_test.sh).
# Not in the sanitizer build: the numbers are the same there, and the sample's converged cloth reference takes
# minutes under ASan (sweep.quick and sweep.parallel run the tool there).
if(PSB_BUILD_TESTS AND NOT PSB_SANITIZE)
  add_test(NAME sweep.reproduce COMMAND sh ${PROJECT_SOURCE_DIR}/tests/bench/sweep_reproduce_test.sh
                                        ${PROJECT_SOURCE_DIR} $<TARGET_FILE:psb-sweep>
                                        ${CMAKE_CURRENT_BINARY_DIR}/sweep-reproduce)
  set_tests_properties(sweep.reproduce PROPERTIES LABELS bench TIMEOUT 600)
endif()
