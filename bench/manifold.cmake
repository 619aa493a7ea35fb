# psb-manifold-bench: ns per box-box call of the solver manifolds (CollideBoxes, ContactManifold.h) against the
# book's FindCollisionFeatures, on the same poses, alternating in one process (docs/soft-solver.md, "Solver manifolds").
add_executable(psb-manifold-bench ${CMAKE_CURRENT_LIST_DIR}/manifold_bench.cpp)
target_link_libraries(psb-manifold-bench PRIVATE psb_geometry psb_math)
