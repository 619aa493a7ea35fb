#include "Demos/SoftDemoPanel.h"

#include <imgui.h>

#include <cstdio>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/ParameterPanel.h"
#include "Demos/Scenes/BookConstants.h"

namespace {
bool StepIsBook(Integrator integrator, float dt) {
    return integrator == Integrator::SemiImplicitEuler && dt == kBookStep;
}
}  // namespace

void DrawSoftDemoPanel(const char* title, const ParameterSet& params, Integrator integrator, float dt,
                       const StabilityMonitor& monitor, float extraHeight) {
    const bool bookStep = StepIsBook(integrator, dt);
    float height = BookPanel::kHeight + extraHeight;
    if (!bookStep) height += BookPanel::kRowHeight;
    if (!monitor.Stable()) height += BookPanel::kRowHeight;
    BeginDemoPanel(title, height, PanelScrollbar::Auto);
    DrawParameterPanel(params);
    if (!bookStep) ImGui::Text("integrator %s, dt %s s", params.Get("integrator").c_str(), params.Get("dt").c_str());
    if (!monitor.Stable()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", monitor.Report().message.c_str());
    ImGui::End();
}

void ReportOnce(const StabilityMonitor& monitor, const char* demo, bool* reported) {
    if (monitor.Stable()) {
        *reported = false;  // a reset restarted the monitor: report the next failure again
        return;
    }
    if (*reported) return;
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
