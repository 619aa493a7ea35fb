#pragma once
// ImGui's OpenGL2 back end for the headless runner. The physics-only build (PSB_WITH_RENDERING=OFF) links no GL
// library, so not this back end either: there the functions below are stand-ins that are never called, as that
// build refuses every run that draws (CheckBackend, Application/RunOutputs.h).

#include <imgui.h>

#if PSB_HAVE_DRAWING
#include <backends/imgui_impl_opengl2.h>
#else
inline bool ImGui_ImplOpenGL2_Init() { return false; }
inline void ImGui_ImplOpenGL2_Shutdown() {}
inline void ImGui_ImplOpenGL2_NewFrame() {}
inline void ImGui_ImplOpenGL2_RenderDrawData(ImDrawData*) {}
#endif
