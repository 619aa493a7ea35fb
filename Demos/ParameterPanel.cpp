#include "Demos/ParameterPanel.h"

#include <imgui.h>

#include <string>

namespace {

using Entry = ParameterSet::Entry;
using Type = ParameterSet::Widget::Type;

/// Draws one widget; true if the user changed its value.
bool DrawWidget(const Entry& e) {
    const ParameterSet::Widget& w = e.widget;
    const char* label = w.label.c_str();
    switch (w.type) {
        case Type::Slider:
            if (e.kind == ParameterSet::Kind::Int)
                return ImGui::SliderInt(label, e.intValue, static_cast<int>(e.min), static_cast<int>(e.max),
                                        w.format.empty() ? "%d" : w.format.c_str());
            return ImGui::SliderFloat(label, e.floatValue, static_cast<float>(e.min), static_cast<float>(e.max),
                                      w.format.empty() ? "%.3f" : w.format.c_str());
        case Type::InputInt:
            if (!ImGui::InputInt(label, e.intValue)) return false;
            if (*e.intValue < e.min) *e.intValue = static_cast<int>(e.min);
            if (*e.intValue > e.max) *e.intValue = static_cast<int>(e.max);
            return true;
        case Type::Checkbox:
            return ImGui::Checkbox(label, e.boolValue);
        case Type::RadioButtons: {
            bool changed = false;
            for (std::size_t i = 0; i < w.choiceLabels.size(); ++i) {
                if (i > 0) ImGui::SameLine();
                changed |= ImGui::RadioButton(w.choiceLabels[i].c_str(), e.intValue, static_cast<int>(i));
            }
            return changed;
        }
        case Type::Button:
            if (ImGui::Button(label) && e.onChange) e.onChange();
            return false;
        case Type::Text:
        case Type::None:
            break;
    }
    return false;
}

}  // namespace

void BeginDemoPanel(const char* title, float height, PanelScrollbar scrollbar) {
    ImGui::SetNextWindowPos(ImVec2(BookPanel::kDemoX, BookPanel::kTop), ImGuiCond_Once);
    ImGui::SetNextWindowSize(ImVec2(BookPanel::kWidth, height), ImGuiCond_Always);
    ImGuiWindowFlags flags = ImGuiWindowFlags_NoResize;
    if (scrollbar == PanelScrollbar::Hidden) flags |= ImGuiWindowFlags_NoScrollbar;
    ImGui::Begin(title, nullptr, flags);
}

void DrawParameterPanel(const ParameterSet& params) {
    float pushedWidth = 0.0f;  // the item width pushed for the current run of widgets; 0: none
    for (const Entry& e : params.Entries()) {
        const ParameterSet::Widget& w = e.widget;
        if (w.type == Type::None) continue;
        std::string text;
        if (w.type == Type::Text) {
            text = e.text ? e.text() : std::string();
            if (text.empty()) continue;
        }
        if (pushedWidth != 0.0f && pushedWidth != w.itemWidth) {
            ImGui::PopItemWidth();
            pushedWidth = 0.0f;
        }
        if (w.sameLine) ImGui::SameLine();
        if (!w.caption.empty()) {
            ImGui::Text("%s", w.caption.c_str());
            ImGui::SameLine();
        }
        if (w.itemWidth != 0.0f && pushedWidth == 0.0f) {
            ImGui::PushItemWidth(w.itemWidth);
            pushedWidth = w.itemWidth;
        }
        if (w.type == Type::Text)
            ImGui::Text("%s", text.c_str());
        else if (DrawWidget(e) && w.appliesAtOnce && e.onChange)
            e.onChange();
    }
    if (pushedWidth != 0.0f) ImGui::PopItemWidth();
}
