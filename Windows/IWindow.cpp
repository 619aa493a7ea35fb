#include "Windows/IWindow.h"

#include <algorithm>
#include <utility>

IWindow::IWindow(std::string windowTitle, int w, int h)
    : width(std::max(1, w)), height(std::max(1, h)), title(std::move(windowTitle)) {}

void IWindow::SetTitle(const std::string& newTitle) {
    title = newTitle;
    titleDirty = true;
}

bool IWindow::GetAndResetTitleDirtyFlag() {
    const bool dirty = titleDirty;
    titleDirty = false;
    return dirty;
}

void IWindow::Resize(int w, int h) {
    width = std::max(1, w);
    height = std::max(1, h);
    OnResize(width, height);
}
