#include "Demos/DemoBase.h"

#include <glad/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/ParameterPanel.h"
#include "Demos/Scenes/AutoModel.h"

DemoBase::DemoBase() = default;

void DemoBase::Initialize(int width, int height) { Resize(width, height); }

void DemoBase::Resize(int width, int height) {
    const float w = static_cast<float>(width > 0 ? width : 1);
    const float h = static_cast<float>(height > 0 ? height : 1);
    camera.Perspective(60.0f, w / h, 0.01f, 1000.0f);
    size = vec2(w, h);
}

void DemoBase::Render() { FixedFunctionOrigin(); }

void DemoBase::Update(float dt) {
    // One mouse button at a time, right before middle before left (docs/book-reference.md §1.1).
    if (mouseRightDown)
        camera.Rotate(mouseDelta, dt);
    else if (mouseMiddleDown)
        camera.Zoom(mouseDelta.y, dt);
    else if (mouseLeftDown)
        camera.Pan(mouseDelta, dt);
    camera.Update(dt);
}

void DemoBase::ImGUI() {
    if (!show_help) return;
    if (configHelpWindow) {
        ImGui::SetNextWindowPos(ImVec2(BookPanel::kDemoX, BookPanel::kHelpTop));
        ImGui::SetNextWindowSize(ImVec2(BookPanel::kWidth, BookPanel::kTallHeight));
        configHelpWindow = false;
    }
    ImGui::Begin("How to use", &show_help, ImGuiWindowFlags_NoResize);
    ImGui::Text("A 3 button mouse is needed to navigate the scene");
    ImGui::Text("Press the left mouse and move the mouse to pan");
    ImGui::Text("Press the middle mouse and move the mouse to zoom");
    ImGui::Text("Press the right mouse and move the mouse to rotate");
    ImGui::End();
}

void DemoBase::DrawPanel(const char* title, float height, PanelScrollbar scrollbar) const {
    BeginDemoPanel(title, height + AutoModelRowHeight(), scrollbar);
    DrawParameterPanel(params);
    ImGui::End();
}

void DemoBase::AddShowHelpButton() {
    params.AddPanelButton(ParameterSet::Widget::Button("Show Help").SameLine(), [this] { show_help = true; });
}

void DemoBase::AddAutoModelKeys() {
    AddAutoModelParameters(&params, &autoModelRequest);
    params.AddPanelText([this] { return AutoModelPanelText(); });
    hasAutoModelKeys = true;
}

std::string DemoBase::AutoModelPanelText() const {
    if (shownModel == nullptr || !shownModel->Active()) return std::string();
    // Deterministic rows (no measured times), so frames with the panel repeat exactly.
    return shownModel->PanelText();
}

float DemoBase::AutoModelRowHeight() const {
    const std::string text = AutoModelPanelText();
    if (text.empty()) return 0.0f;
    // One row, then one text line per further line (ImGui draws a multi-line text as one item).
    const auto lines = std::count(text.begin(), text.end(), '\n');
    return BookPanel::kRowHeight + ImGui::GetTextLineHeight() * static_cast<float>(lines);
}

void DemoBase::UseBookCamera(float zoom) {
    camera.SetTarget(vec3(3.75622f, 2.98255f, 0.0f));
    camera.SetZoom(zoom);
    camera.SetRotation(vec2(-67.9312f, 19.8f));
}

void DemoBase::EnableBookLighting() {
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
}

void DemoBase::InitializeBookView() {
    EnableBookLighting();
    SetLightDirection(vec3(0.5f, 1.0f, -1.5f));
}

void DemoBase::SetMouseState(bool left, bool middle, bool right, const vec2& delta, const vec2& mouse) {
    mouseLeftDown = left;
    mouseMiddleDown = middle;
    mouseRightDown = right;
    mouseDelta = delta;
    mousePos = mouse;
}

bool DemoBase::StateIsFinite(std::string* where) const {
    std::vector<BodyState> bodies;
    CollectState(&bodies);
    for (const BodyState& b : bodies) {
        const vec3* vectors[2] = {&b.position, &b.velocity};
        const char* names[2] = {"position", "velocity"};
        for (int v = 0; v < 2; ++v) {
            const vec3& x = *vectors[v];
            if (std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)) continue;
            if (where != nullptr) {
                std::ostringstream out;
                out << "body " << b.body << " (" << b.kind << ") " << names[v] << " = (" << x.x << ", " << x.y << ", "
                    << x.z << ")";
                *where = out.str();
            }
            return false;
        }
    }
    return true;
}
