#include "Windows/DemoWindow.h"

#include <glad/gl.h>
#include <imgui.h>

#include <cmath>
#include <vector>

#include "Demos/DemoBase.h"
#include "Demos/DemoRegistry.h"
#include "Demos/ParameterPanel.h"

namespace {
/// The three chapter buttons of the default mode (docs/book-reference.md §1.7).
struct ChapterButton {
    const char* id;
    const char* runLabel;  // leading space, as the book
    const char* stopLabel;
};
constexpr ChapterButton kChapterButtons[3] = {
    {"ch14", " Run Chapter 14", "Stop Chapter 14"},
    {"ch15", " Run Chapter 15", "Stop Chapter 15"},
    {"ch16", " Run Chapter 16", "Stop Chapter 16"},
};
}  // namespace

// The book's fixedFPS / targetFPS were never read: the host's fixed step is the demo's physics step
// (DemoBase::PhysicsStep) or --dt, and the frame time is --fps.
DemoWindow::DemoWindow(const std::string& windowTitle, int w, int h) : GLWindow(windowTitle, w, h) {}

DemoWindow::~DemoWindow() { StopDemo(); }

void DemoWindow::OnInitialize() {
    if (drawing)
        GLWindow::OnInitialize();
    else
        OnResize(width, height);
    selectAll = false;  // the book's constructor sets it, OnInitialize clears it
}

void DemoWindow::OnRender() {
    GLWindow::OnRender();
    if (!demo) return;
    SetGLProjection(demo->camera.GetProjectionMatrix().asArray);
    SetGLModelView(demo->camera.GetViewMatrix().asArray);
    demo->Render();
}

void DemoWindow::OnResize(int w, int h) {
    if (drawing) GLWindow::OnResize(w, h);
    if (demo) demo->Resize(w, h);
}

void DemoWindow::OnUpdate(float /*deltaTime*/) {
    if (!uiVisible) return;
    MainPanel();
    if (demo) demo->ImGUI();
}

void DemoWindow::MainPanel() {
    ImGui::SetNextWindowPos(ImVec2(BookPanel::kMainX, BookPanel::kTop), ImGuiCond_Once);
    ImGui::SetNextWindowSize(ImVec2(BookPanel::kWidth, selectAll ? BookPanel::kListHeight : BookPanel::kHeight),
                             ImGuiCond_Always);
    ImGui::Begin("Physics Demo", nullptr, ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoScrollbar);
    const float fps = nominalFrameMs > 0.0f ? 1000.0f / nominalFrameMs : 0.0f;
    ImGui::Text("Application average %.3f ms/frame (%.1f FPS)", static_cast<double>(nominalFrameMs),
                static_cast<double>(fps));

    if (selectAll) {
        const std::vector<DemoInfo>& demos = AllDemos();
        std::vector<const char*> titles;
        int current = -1;
        for (std::size_t i = 0; i < demos.size(); ++i) {
            titles.push_back(demos[i].title.c_str());
            if (demos[i].id == demoId) current = static_cast<int>(i);
        }
        int selected = current;
        ImGui::PushItemWidth(BookPanel::kListWidth);
        if (ImGui::ListBox("##demos", &selected, titles.data(), static_cast<int>(titles.size()), 5) &&
            selected != current && selected >= 0)
            StartDemo(demos[static_cast<std::size_t>(selected)].id);
        ImGui::PopItemWidth();  // erratum 5.2-26: the book never pops
    } else {
        for (int i = 0; i < 3; ++i) {
            const ChapterButton& b = kChapterButtons[i];
            const bool running = demoId == b.id;
            if (i > 0) ImGui::SameLine();
            if (ImGui::Button(running ? b.stopLabel : b.runLabel)) {
                if (running)
                    StopDemo();
                else
                    StartDemo(b.id);
            }
        }
    }
    ImGui::End();
}

void DemoWindow::OnFixedUpdate(float fixedDeltaTime) {
    if (!demo) return;
    const vec2 pos = GetMousePosition();
    const vec2 delta((pos.x - prevMousePos.x) / static_cast<float>(width),
                     (pos.y - prevMousePos.y) / static_cast<float>(height));
    demo->SetMouseState(MouseButtonDown(MouseButton::Left), MouseButtonDown(MouseButton::Middle),
                        MouseButtonDown(MouseButton::Right), delta, pos);
    demo->Update(fixedDeltaTime);
    prevMousePos = pos;
}

void DemoWindow::OnShutdown() { StopDemo(); }

bool DemoWindow::StartDemo(const std::string& id) {
    const DemoInfo* info = FindDemo(id);
    if (info == nullptr) {
        StopDemo();
        return false;
    }
    return StartDemo(info->create(), id);
}

bool DemoWindow::StartDemo(std::unique_ptr<DemoBase> created, const std::string& id) {
    StopDemo();
    demo = std::move(created);
    if (!demo) return false;
    demoId = id;
    demo->Initialize(width, height);
    if (drawing) demo->InitializeDrawing();
    demo->camera.Update(0.0f);  // erratum 5.2-29: the book shows an identity view until the first fixed step
    prevMousePos = GetMousePosition();
    return true;
}

void DemoWindow::StopDemo() {
    if (demo) demo->Shutdown();
    demo.reset();
    demoId.clear();
}

void DemoWindow::SetNominalFrameTime(float milliseconds) {
    nominalFrameMs = std::isfinite(milliseconds) && milliseconds > 0.0f ? milliseconds : 16.0f;
}
