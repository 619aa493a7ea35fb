# render_bench: frames per second of each demo at 800x600 split into render, readback and PNG encode,
# against a bare OSMesa render-and-read loop; PNG encoder/level comparison. Figures in docs/app.md.
if(TARGET psb_app)
  add_executable(render_bench ${CMAKE_CURRENT_LIST_DIR}/render_bench.cpp)
  target_include_directories(render_bench SYSTEM PRIVATE /usr/include/stb)
  target_link_libraries(render_bench PRIVATE psb_app psb_platform psb_options)
endif()
