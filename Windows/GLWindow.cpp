#include "Windows/GLWindow.h"

#include <glad/gl.h>

#include <algorithm>

namespace {
unsigned Bit(MouseButton b) { return 1u << (static_cast<int>(b) - 1); }
}  // namespace

GLWindow::GLWindow(const std::string& windowTitle, int w, int h) : IWindow(windowTitle, w, h) {}

void GLWindow::OnInitialize() {
    glClearColor(0.5f, 0.6f, 0.7f, 1.0f);  // RGB (128, 153, 178), docs/book-reference.md §1.3
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // GL defaults: cull back faces, CCW is front
    OnResize(width, height);
}

void GLWindow::OnRender() { glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT); }

void GLWindow::OnResize(int w, int h) { glViewport(0, 0, w, h); }

void GLWindow::OnMouseMove(int x, int y) { mousePos = vec2(static_cast<float>(x), static_cast<float>(y)); }
void GLWindow::OnMouseDown(MouseButton button) { mouseButtons |= Bit(button); }
void GLWindow::OnMouseUp(MouseButton button) { mouseButtons &= ~Bit(button); }

void GLWindow::OnKeyDown(int keyCode) {
    if (keyCode >= 0 && keyCode < 256) keyboardState[static_cast<std::size_t>(keyCode)] = true;
}
void GLWindow::OnKeyUp(int keyCode) {
    if (keyCode >= 0 && keyCode < 256) keyboardState[static_cast<std::size_t>(keyCode)] = false;
}

bool GLWindow::MouseButtonDown(MouseButton button) const { return (mouseButtons & Bit(button)) != 0; }

bool GLWindow::KeyDown(int keyCode) const {
    return keyCode >= 0 && keyCode < 256 && keyboardState[static_cast<std::size_t>(keyCode)];
}

void GLWindow::SetClearColor(float r, float g, float b) {
    glClearColor(std::clamp(r, 0.0f, 1.0f), std::clamp(g, 0.0f, 1.0f), std::clamp(b, 0.0f, 1.0f), 1.0f);
}

void GLWindow::SetGLProjection(const float* matrix) {
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(matrix);
    glMatrixMode(GL_MODELVIEW);
}

void GLWindow::SetGLModelView(const float* matrix) {
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(matrix);
}
