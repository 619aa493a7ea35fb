# psb-sweep: reference problems x settings -> CSV (docs/sweep.md). Links the GL-free layers only.
add_executable(psb-sweep ${CMAKE_CURRENT_LIST_DIR}/sweep/SweepMain.cpp ${CMAKE_CURRENT_LIST_DIR}/sweep/Sweep.cpp
                         ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsParticle.cpp
                         ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsRigid.cpp
                         ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsCloth.cpp)
target_link_libraries(psb-sweep PRIVATE psb_scenes psb_physics psb_options)

# CI runs the small grid and checks what its numbers must show (tests/bench/sweep_quick_test.sh).
if(PSB_BUILD_TESTS)
  add_test(NAME sweep.quick COMMAND sh ${PROJECT_SOURCE_DIR}/tests/bench/sweep_quick_test.sh
                                    $<TARGET_FILE:psb-sweep> ${CMAKE_CURRENT_BINARY_DIR}/sweep-quick)
  set_tests_properties(sweep.quick PROPERTIES LABELS bench TIMEOUT 600)
endif()
