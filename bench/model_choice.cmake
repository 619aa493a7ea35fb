# psb-model-choice-bench: `model: auto` against the sweep (docs/model-choice-validation.md). Links the GL-free layers
# and the sweep's problems (their references and errors are the validation's).
add_executable(
  psb-model-choice-bench
  ${CMAKE_CURRENT_LIST_DIR}/model_choice/ModelChoiceBench.cpp ${CMAKE_CURRENT_LIST_DIR}/model_choice/ReferenceProblems.cpp
  ${CMAKE_CURRENT_LIST_DIR}/model_choice/Runs.cpp ${CMAKE_CURRENT_LIST_DIR}/model_choice/SweepRows.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sweep/Sweep.cpp ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsParticle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsRigid.cpp ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsCloth.cpp)
target_link_libraries(psb-model-choice-bench PRIVATE psb_scenes psb_physics psb_files psb_options)
get_filename_component(PSB_MODEL_CHOICE_REPO ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
target_compile_definitions(psb-model-choice-bench PRIVATE PSB_SOURCE_DIR="${PSB_MODEL_CHOICE_REPO}")

# The small grid (a few fast problems at two budgets): the scene files are the sweep's problems (--check), and auto's
# error stays within 3x the budget (not the timing: timings are reported by the full bench, never asserted).
if(PSB_BUILD_TESTS)
  add_test(NAME model_choice.quick COMMAND sh ${PROJECT_SOURCE_DIR}/tests/bench/model_choice_test.sh
                                           ${PROJECT_SOURCE_DIR} $<TARGET_FILE:psb-model-choice-bench>
                                           ${CMAKE_CURRENT_BINARY_DIR}/model-choice-quick)
  set_tests_properties(model_choice.quick PROPERTIES LABELS bench TIMEOUT 300)
endif()

# The generator of problems nobody tuned (auto_validate.py, docs/model-choice-validation.md "Problems nobody tuned")
# drives the release program; its CTest checks the machinery on a small seeded slice (exact answers against
# independent integrations and fine fixed runs, the CSV's columns, a refusal's grid), never auto's figures.
if(PSB_BUILD_TESTS AND TARGET physics-sandbox)
  find_package(Python3 COMPONENTS Interpreter REQUIRED)
  add_test(NAME model_choice.auto_validate
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/bench/auto_validate_test.py
                   $<TARGET_FILE:physics-sandbox> ${CMAKE_CURRENT_BINARY_DIR}/auto-validate-quick)
  set_tests_properties(model_choice.auto_validate PROPERTIES LABELS bench TIMEOUT 300)
endif()
