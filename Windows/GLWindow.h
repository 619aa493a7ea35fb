#pragma once
// IWindow with the book's basic OpenGL state and input bookkeeping (docs/book-reference.md §1.1, §1.3). Needs a current
// OpenGL 2.1 context (loaded through GLAD) for OnInitialize, OnRender, OnResize and the SetGL* helpers.

#include <array>

#include "Math/vectors.h"
#include "Windows/IWindow.h"

class GLWindow : public IWindow {
public:
    GLWindow(const std::string& title, int width, int height);

    /// Clear colour (0.5, 0.6, 0.7, 1), depth test and back-face culling (CCW front) on, then OnResize.
    void OnInitialize() override;
    /// Clears colour, depth and stencil.
    void OnRender() override;
    /// glViewport(0, 0, w, h).
    void OnResize(int width, int height) override;
    void OnMouseMove(int x, int y) override;
    void OnMouseDown(MouseButton button) override;
    void OnMouseUp(MouseButton button) override;
    void OnKeyDown(int keyCode) override;
    void OnKeyUp(int keyCode) override;

    /// Last cursor position in pixels (top-left origin).
    vec2 GetMousePosition() const { return mousePos; }
    /// The book's MouseButonDown.
    bool MouseButtonDown(MouseButton button) const;
    /// False for codes outside 0..255.
    bool KeyDown(int keyCode) const;
    /// Each channel clamped to [0, 1]; takes effect at the next clear.
    void SetClearColor(float r, float g, float b);
    /// Loads a row-major book matrix (its array is GL's column-major layout) into PROJECTION / MODELVIEW.
    void SetGLProjection(const float* matrix);
    void SetGLModelView(const float* matrix);

protected:
    vec2 mousePos;
    unsigned mouseButtons = 0;  // bit (code - 1) per MouseButton
    std::array<bool, 256> keyboardState{};
};
