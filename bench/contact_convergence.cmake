# psb-contact-convergence: contact problems with exact answers at a grid of steps, every solver (docs/soft-solver.md,
# "Convergence of the contact solvers"). GL-free.
add_executable(psb-contact-convergence ${CMAKE_CURRENT_LIST_DIR}/contact_convergence.cpp)
target_link_libraries(psb-contact-convergence PRIVATE psb_scenes psb_physics psb_options)

# The tool runs and refuses bad input (the convergence itself is checked by tests/physics/ContactConvergence_test).
if(PSB_BUILD_TESTS)
  add_test(NAME contact_convergence.cli
           COMMAND sh -c "$<TARGET_FILE:psb-contact-convergence> --quick --problem box-slide-stop | grep -q '^box-slide-stop,soft,0.001,6,' && ! $<TARGET_FILE:psb-contact-convergence> --problem nope 2>/dev/null && ! $<TARGET_FILE:psb-contact-convergence> --dt 0 2>/dev/null")
  set_tests_properties(contact_convergence.cli PROPERTIES LABELS bench TIMEOUT 60)
endif()
