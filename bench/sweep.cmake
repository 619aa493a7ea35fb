# psb-sweep (issue 7): reference problems x settings -> CSV (docs/sweep.md). Links the GL-free layers only.
add_executable(psb-sweep ${CMAKE_CURRENT_LIST_DIR}/sweep/SweepMain.cpp ${CMAKE_CURRENT_LIST_DIR}/sweep/Sweep.cpp
                         ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsParticle.cpp
                         ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsRigid.cpp
                         ${CMAKE_CURRENT_LIST_DIR}/sweep/ProblemsCloth.cpp)
target_include_directories(psb-sweep PRIVATE ${CMAKE_CURRENT_LIST_DIR}/sweep)
target_link_libraries(psb-sweep PRIVATE psb_scenes psb_physics psb_options)
