#include "Demos/SoftDemoPanel.h"

#include <imgui.h>

#include <cstdio>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"

namespace {
constexpr float kBookDt = 0.03f;
constexpr float kRowHeight = 21.0f;  // one ImGui text row at the default font
bool StepIsBook(Integrator integrator, float dt) {
    return integrator == Integrator::SemiImplicitEuler && dt == kBookDt;
}
}  // namespace

void BeginSoftPanel(const char* title, Integrator integrator, float dt, const StabilityMonitor& monitor) {
    float height = 75.0f;
    if (!StepIsBook(integrator, dt)) height += kRowHeight;
    if (!monitor.Stable()) height += kRowHeight;
    ImGui::SetNextWindowPos(ImVec2(400.0f, 10.0f), ImGuiCond_Once);
    ImGui::SetNextWindowSize(ImVec2(370.0f, height), ImGuiCond_Always);
    ImGui::Begin(title, nullptr, ImGuiWindowFlags_NoResize);
}

void EndSoftPanel(const ParameterSet& params, const StabilityMonitor& monitor) {
    const std::string integrator = params.Get("integrator");
    const std::string dt = params.Get("dt");
    if (integrator != "euler" || params.Find("dt") == nullptr || *params.Find("dt")->floatValue != kBookDt)
        ImGui::Text("integrator %s, dt %s s", integrator.c_str(), dt.c_str());
    if (!monitor.Stable()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", monitor.Report().message.c_str());
    ImGui::End();
}

void ReportOnce(const StabilityMonitor& monitor, const char* demo, bool* reported) {
    if (monitor.Stable() || *reported) return;
    std::fprintf(stderr, "physics-sandbox: %s: %s\n", demo, monitor.Report().message.c_str());
    *reported = true;
}

void RenderSystemOrConstraints(const PhysicsSystem& system, const StabilityMonitor& monitor) {
    if (monitor.Stable()) {
        Render(system);
        return;
    }
    const std::vector<OBB>& constraints = system.Constraints();
    for (std::size_t i = 0; i < constraints.size(); ++i) {
        if (i == 0)
            SetLightColors(BookColors::kGroundAmbient, BookColors::kGroundDiffuse);
        else
            SetLightColors(BookColors::kConstraintAmbient, BookColors::kConstraintDiffuse);
        Render(constraints[i]);
    }
}
